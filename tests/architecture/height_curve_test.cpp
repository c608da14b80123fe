#include "architecture/height_curve.hpp"

#include <gtest/gtest.h>

namespace heliostand {
namespace {

TEST(HeightCurve, ExponentIsChapmanRichardsOneOverOneMinusM) {
  // p = 1 / (1 - 0.3639) = 1 / 0.6361 = 1.57208
  EXPECT_NEAR(height_curve_exponent(SpeciesParameters{}), 1.57208, 1e-5);
}

TEST(HeightCurve, SiteClassOneExampleMatchesHandValues) {
  const SpeciesParameters species;  // A = 28, k = 0.0348, m = 0.3639
  // t = 35: k t = 1.218, exp(-1.218) = 0.295821, 1 - 0.295821 = 0.704179,
  //         ln 0.704179 = -0.350723, × 1.57208 = -0.551365, exp = 0.576163, × 28 = 16.1326 m
  EXPECT_NEAR(tree_height_m(species, 28.0, 35.0), 16.1326, 1e-3);
  // t = 10: 1 - exp(-0.348) = 0.293901, ln = -1.224512, × 1.57208 = -1.925030, exp = 0.145871, × 28 = 4.0844 m
  EXPECT_NEAR(tree_height_m(species, 28.0, 10.0), 4.0844, 1e-3);
  // t = 60: 1 - exp(-2.088) = 0.876065, ln = -0.132315, × 1.57208 = -0.208009, exp = 0.812199, × 28 = 22.7416 m
  EXPECT_NEAR(tree_height_m(species, 28.0, 60.0), 22.7416, 1e-3);
  // The rejected reading p = m would give 28 × 0.293901^0.3639 = 17.93 m at age 10.
  EXPECT_LT(tree_height_m(species, 28.0, 10.0), 10.0);
}

TEST(HeightCurve, PlantedAtZeroHeight) {
  EXPECT_EQ(tree_height_m(SpeciesParameters{}, 28.0, 0.0), 0.0);
}

TEST(HeightCurve, AsymptoteForARecordPassesThroughIt) {
  const SpeciesParameters species;
  // 16.1326 m at 35 years is the A = 28 curve (above); 10 m at 35 needs A = 10 / 0.576163 = 17.356 m.
  EXPECT_NEAR(site_asymptote_for(species, 16.1326, 35.0), 28.0, 1e-3);
  EXPECT_NEAR(site_asymptote_for(species, 10.0, 35.0), 17.356, 1e-3);
  EXPECT_NEAR(tree_height_m(species, site_asymptote_for(species, 12.5, 27.0), 27.0), 12.5, 1e-9);
}

}  // namespace
}  // namespace heliostand
