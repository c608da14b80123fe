#include "records/stand_metrics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace heliostand {
namespace {

TEST(StandMetrics, PerHectareValuesOfThreeTreesOnTheHundredthOfAHectare) {
  const std::vector<TreeMeasurement> trees = {{10, 10, 0.1}, {20, 15, 0.2}, {30, 20, 0.3}};
  const StandMetrics m = measure_stand(trees, 0.01);
  EXPECT_DOUBLE_EQ(m.stems_per_ha, 300.0);
  // π (0.05² + 0.10² + 0.15²) m² = 0.035 π m² on 0.01 ha
  EXPECT_NEAR(m.basal_area_m2_per_ha, 3.5 * std::numbers::pi, 1e-12);
  EXPECT_NEAR(m.qmd_cm, std::sqrt(1400.0 / 3.0), 1e-12);  // sqrt((100 + 400 + 900) / 3) = 21.602 cm
  EXPECT_DOUBLE_EQ(m.mean_height_m, 15.0);
  EXPECT_DOUBLE_EQ(m.top_height_m, 20.0);  // 100/ha on 0.01 ha = one tree: the thickest
  EXPECT_NEAR(m.volume_m3_per_ha, 60.0, 1e-12);
}

TEST(StandMetrics, LoreysHeightWeighsEachTreeByItsBasalArea) {
  // g ∝ dbh²: 20 cm → 0.01 π m², 40 cm → 0.04 π m². Hg = (0.01·15 + 0.04·25) / 0.05 = 23 m; the plain mean is 20 m.
  const std::vector<TreeMeasurement> two = {{20, 15, 0}, {40, 25, 0}};
  EXPECT_NEAR(measure_stand(two, 0.1).hg_m, 23.0, 1e-12);
  EXPECT_DOUBLE_EQ(measure_stand(two, 0.1).mean_height_m, 20.0);
  // A sapling below breast height has no basal area: it lowers the mean height, not Hg.
  const std::vector<TreeMeasurement> with_sapling = {{20, 15, 0}, {40, 25, 0}, {0, 1.1, 0}};
  EXPECT_NEAR(measure_stand(with_sapling, 0.1).hg_m, 23.0, 1e-12);
  EXPECT_TRUE(std::isnan(measure_stand(std::vector<TreeMeasurement>{{0, 1.1, 0}}, 0.1).hg_m));
}

TEST(StandMetrics, TopHeightTreeCountIsHundredPerHectareRoundedAtLeastOne) {
  EXPECT_EQ(top_height_tree_count(1.0), 100);
  EXPECT_EQ(top_height_tree_count(0.05), 5);
  EXPECT_EQ(top_height_tree_count(0.026), 3);  // 2.6 trees → 3
  EXPECT_EQ(top_height_tree_count(0.004), 1);  // 0.4 trees → at least one
}

TEST(StandMetrics, TopHeightFollowsTheThickestTreesNotTheTallest) {
  // The tallest tree (22 m) is not among the two thickest; 0.02 ha → 2 trees: dbh 30 (18 m) and 25 (16 m).
  const std::vector<TreeMeasurement> trees = {{20, 22, 0}, {30, 18, 0}, {10, 12, 0}, {25, 16, 0}};
  EXPECT_DOUBLE_EQ(top_height_m(trees, 0.02), 17.0);
  // More trees requested than present: the mean of all.
  EXPECT_DOUBLE_EQ(top_height_m(trees, 1.0), (22.0 + 18 + 12 + 16) / 4);
}

TEST(StandMetrics, EmptyStandHasZeroDensityAndUndefinedMeans) {
  const StandMetrics m = measure_stand({}, 0.1);
  EXPECT_EQ(m.stems_per_ha, 0.0);
  EXPECT_EQ(m.basal_area_m2_per_ha, 0.0);
  EXPECT_TRUE(std::isnan(m.qmd_cm));
  EXPECT_TRUE(std::isnan(m.mean_height_m));
  EXPECT_TRUE(std::isnan(m.hg_m));
  EXPECT_TRUE(std::isnan(m.top_height_m));
}

TEST(StandMetrics, RejectsANonPositivePlotArea) {
  EXPECT_THROW(measure_stand({}, 0.0), std::invalid_argument);
  EXPECT_THROW(measure_stand({}, -0.05), std::invalid_argument);
}

}  // namespace
}  // namespace heliostand
