#include "architecture/stem_taper.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "geometry/angles.hpp"

namespace heliostand {
namespace {

TEST(StemTaper, InsideTheCrownUsesTheInCrownCoefficients) {
  const StemTaper taper{16.0, 8.0};
  // h = 10 m: 2.245 × (16 - 10)^0.951 = 2.245 × 5.495685 = 12.3378 cm
  EXPECT_NEAR(taper.diameter_cm(SpeciesParameters{}, 10.0), 12.3378, 1e-3);
}

TEST(StemTaper, BelowTheCrownUsesTheBelowCrownCoefficientsAndGivesDbh) {
  const StemTaper taper{16.0, 8.0};
  // h = 1.3 m: 3.336 × (16 - 1.3)^0.771 = 3.336 × 7.943313 = 26.4989 cm
  EXPECT_NEAR(taper.diameter_cm(SpeciesParameters{}, 1.3), 26.4989, 1e-3);
  EXPECT_NEAR(taper.dbh_cm(SpeciesParameters{}), 26.4989, 1e-3);
}

TEST(StemTaper, NoDbhBelowBreastHeightAndZeroAtTheTop) {
  EXPECT_EQ((StemTaper{1.2, 0.0}.dbh_cm(SpeciesParameters{})), 0.0);
  EXPECT_EQ((StemTaper{10.0, 3.0}.diameter_cm(SpeciesParameters{}, 10.0)), 0.0);
}

TEST(StemTaper, VolumeOfAStemWhollyInTheCrownMatchesTheClosedForm) {
  // Crown base at the ground: V = π/4 · 1e-4 · 2.245² · 10^(2·0.951+1) / (2·0.951+1)
  //   = 0.785398 · 1e-4 · 5.040025 · 797.9947 / 2.902 = 0.108849 m³
  EXPECT_NEAR((StemTaper{10.0, 0.0}.volume_m3(SpeciesParameters{})), 0.108849, 1e-5);
}

TEST(StemTaper, VolumeMatchesNumericalIntegrationOfEq2WithACrownBase) {
  const SpeciesParameters species;
  const StemTaper taper{16.0, 7.0};
  // Midpoint rule over 200 000 slices of π/4 (D/100)², independent of the closed form.
  const int slices = 200000;
  const double dh = taper.height_m / slices;
  double volume = 0.0;
  for (int i = 0; i < slices; ++i) {
    const double d = taper.diameter_cm(species, (i + 0.5) * dh) / 100.0;
    volume += pi / 4.0 * d * d * dh;
  }
  EXPECT_NEAR(taper.volume_m3(species), volume, 1e-6);
}

}  // namespace
}  // namespace heliostand
