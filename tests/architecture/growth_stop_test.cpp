#include "architecture/growth_stop.hpp"

#include <gtest/gtest.h>

namespace heliostand {
namespace {

TEST(GrowthStop, EachOrderAddsTheActivity) {
  SpeciesParameters species;
  species.activity = -8.0;
  // eq. 12: 18, 18 - 8 = 10, 10 - 8 = 2
  EXPECT_NEAR(growth_stop_years(species, 18.0, 1), 18.0, 1e-12);
  EXPECT_NEAR(growth_stop_years(species, 18.0, 2), 10.0, 1e-12);
  EXPECT_NEAR(growth_stop_years(species, 18.0, 3), 2.0, 1e-12);
}

TEST(GrowthStop, BranchGrowsUntilItsGrowthStopYears) {
  EXPECT_TRUE(still_growing(0.0, 18.0));
  EXPECT_TRUE(still_growing(17.0, 18.0));
  EXPECT_FALSE(still_growing(18.0, 18.0));
  EXPECT_FALSE(still_growing(0.0, 0.0));  // an order with no growth years never flushes
}

TEST(GrowthStop, DeadBranchLossRateIsYearsSinceStopOverAttachedYears) {
  SpeciesParameters species;
  species.dead_branch_attached_years = 10.0;
  EXPECT_NEAR(dead_branch_loss_fraction(species, 3.0), 0.3, 1e-12);  // eq. 13: 3 / 10
  EXPECT_EQ(dead_branch_loss_fraction(species, 0.0), 0.0);
  EXPECT_EQ(dead_branch_loss_fraction(species, 14.0), 1.0);  // all gone, clamped
}

}  // namespace
}  // namespace heliostand
