#include "architecture/branch_angle.hpp"

#include <gtest/gtest.h>

namespace heliostand {
namespace {

TEST(BranchAngle, SeedExampleRateIsThreeTenthsDegreePerYear) {
  // eq. 5: (90 - 60) / 100 = 0.3 °/year
  EXPECT_NEAR(branch_angle_rate_deg_per_year(SpeciesParameters{}), 0.3, 1e-12);
}

TEST(BranchAngle, DroopIsBranchAgeTimesAnnualDroop) {
  // eq. 6: 10 × 0.5 = 5°
  EXPECT_NEAR(branch_droop_deg(SpeciesParameters{}, 10.0), 5.0, 1e-12);
}

TEST(BranchAngle, NewBranchLeavesAtD0AndLowersWithAge) {
  const SpeciesParameters species;
  EXPECT_NEAR(first_order_branch_angle_deg(species, 0.0), 60.0, 1e-12);
  // eq. 4 at 10 years since emergence: 10 × 0.3 + 60 + 10 × 0.5 = 3 + 60 + 5 = 68°
  EXPECT_NEAR(first_order_branch_angle_deg(species, 10.0), 68.0, 1e-12);
  SpeciesParameters weeping = species;
  weeping.annual_droop_deg = 2.0;  // 10 × 0.3 + 60 + 10 × 2 = 83°
  EXPECT_NEAR(first_order_branch_angle_deg(weeping, 10.0), 83.0, 1e-12);
}

}  // namespace
}  // namespace heliostand
