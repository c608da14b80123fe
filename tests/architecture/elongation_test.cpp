#include "architecture/elongation.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "geometry/angles.hpp"

namespace heliostand {
namespace {

TEST(Elongation, CrownAngleGrowsWithTreeAge) {
  const SpeciesParameters species;
  EXPECT_NEAR(crown_angle_deg(species, 1.0), 20.0, 1e-12);
  // eq. 10 at 35 years: 20 × 35^0.18 = 20 × 1.896410 = 37.9282°
  EXPECT_NEAR(crown_angle_deg(species, 35.0), 37.9282, 1e-3);
}

TEST(Elongation, FirstOrderInitialElongationByLawOfSines) {
  const SpeciesParameters species;
  // eq. 9 at age 1 (crown angle 20°), d0 = 60°, height growth 0.5 m:
  //   0.5 / sin(180 - 20 - 60) × sin 20 = 0.5 / 0.984808 × 0.342020 = 0.173648 m
  EXPECT_NEAR(first_order_initial_elongation_m(species, 0.5, 1.0), 0.173648, 1e-6);
}

TEST(Elongation, InitialElongationPutsTheBranchTipOnTheCrownCone) {
  const SpeciesParameters species;
  const double growth = 0.4, age = 20.0;
  const double e = first_order_initial_elongation_m(species, growth, age);
  // Whorl at the origin, new top at (0, growth); tip along d0 from the stem axis.
  const double x = e * std::sin(radians(species.initial_branch_angle_deg));
  const double z = e * std::cos(radians(species.initial_branch_angle_deg));
  EXPECT_NEAR(degrees(std::atan2(x, growth - z)), crown_angle_deg(species, age), 1e-9);
}

TEST(Elongation, NoConeNoElongation) {
  SpeciesParameters species;
  species.initial_crown_angle_deg = 130.0;  // 130 + 60 ≥ 180: the triangle does not close
  EXPECT_EQ(first_order_initial_elongation_m(species, 0.5, 1.0), 0.0);
}

TEST(Elongation, TotalAndAnnualElongation) {
  // eq. 8: 0.2 × 4^0.9 = 0.2 × 3.482202 = 0.696440 m
  EXPECT_NEAR(total_elongation_m(0.2, 4.0, 0.9), 0.696440, 1e-6);
  // eq. 7: 0.2 × (4^0.9 - 3^0.9) = 0.2 × (3.482202 - 2.687875) = 0.158865 m
  EXPECT_NEAR(annual_elongation_m(0.2, 4, 0.9), 0.158865, 1e-6);
  // The first flush is the initial elongation.
  EXPECT_NEAR(annual_elongation_m(0.2, 1, 0.9), 0.2, 1e-12);
}

}  // namespace
}  // namespace heliostand
