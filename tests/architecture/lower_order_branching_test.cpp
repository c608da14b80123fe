#include "architecture/lower_order_branching.hpp"

#include <gtest/gtest.h>

namespace heliostand {
namespace {

TEST(LowerOrderBranching, InitialElongationIsLinearInTheParent) {
  SpeciesParameters species;
  species.second_order_elongation_ratio = 0.45;
  EXPECT_NEAR(lower_order_initial_elongation_m(species, 0.2), 0.09, 1e-12);  // 0.45 × 0.2
}

TEST(LowerOrderBranching, SecondOrderPairsAlwaysFlushOnLongEnoughParents) {
  SpeciesParameters species;
  species.min_parent_length_m = 0.06;
  EXPECT_EQ(lateral_occurrence_probability(species, 2, 0.06), 1.0);
  EXPECT_EQ(lateral_occurrence_probability(species, 2, 0.059), 0.0);  // parent shorter than the minimum
}

TEST(LowerOrderBranching, ThirdOrderOccurrenceFollowsTheSeedTable) {
  SpeciesParameters species;
  species.min_parent_length_m = 0.0;  // let the table alone decide
  const struct { double cm, p; } table[] = {{7.0, 1.0},  {6.5, 1.0},   {6.4, 0.975}, {5.5, 0.975}, {5.2, 0.95},
                                            {4.5, 0.72}, {3.7, 0.50},  {3.2, 0.295}, {2.5, 0.10},  {2.0, 0.10},
                                            {1.99, 0.0}, {0.5, 0.0}};
  for (const auto& row : table)
    EXPECT_NEAR(lateral_occurrence_probability(species, 3, row.cm / 100.0), row.p, 1e-12) << row.cm << " cm";
}

TEST(LowerOrderBranching, NoOrderBeyondTheLast) {
  SpeciesParameters species;
  species.max_order = 3;
  EXPECT_EQ(lateral_occurrence_probability(species, 4, 0.5), 0.0);
}

}  // namespace
}  // namespace heliostand
