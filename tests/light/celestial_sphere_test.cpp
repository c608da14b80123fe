#include "light/celestial_sphere.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "geometry/angles.hpp"

namespace heliostand {
namespace {

TEST(CelestialSphere, PatchesTileTheWholeSphereAndEachHemisphere) {
  LightParameters p;  // V = 16, H = 32
  const CelestialSphere sky(p);
  ASSERT_EQ(sky.patches().size(), 16u * 32u);
  double total = 0, upper = 0;
  for (const auto& patch : sky.patches()) {
    total += patch.solid_angle;
    if (patch.band < 8) upper += patch.solid_angle;
    EXPECT_NEAR(glm::length(patch.direction), 1.0, 1e-12);
    EXPECT_EQ(patch.direction.z > 0, patch.band < 8);  // no band centre lies on the horizon
  }
  EXPECT_NEAR(total, 4 * pi, 1e-12);
  EXPECT_NEAR(upper, 2 * pi, 1e-12);
}

TEST(CelestialSphere, ZenithBandIsASphericalCapSplitIntoSectors) {
  LightParameters p;
  p.sky_bands = 4;
  p.sky_sectors = 8;
  const CelestialSphere sky(p);
  // band 0 spans polar angles 0..45 deg: cap area 2 pi (1 - cos 45 deg), split in 8 sectors
  EXPECT_NEAR(sky.patches()[0].solid_angle, 2 * pi * (1 - std::sqrt(0.5)) / 8, 1e-12);
  // its centre is at polar 22.5 deg, azimuth 22.5 deg
  const glm::dvec3 n = sky.patches()[0].direction;
  EXPECT_NEAR(n.z, std::cos(pi / 8), 1e-12);
  EXPECT_NEAR(std::atan2(n.y, n.x), pi / 8, 1e-12);
}

TEST(CelestialSphere, UpperPatchesCarrySkyLightAndLowerPatchesGroundReflection) {
  LightParameters p;
  p.intensity_ratio = 2.0;
  p.sky_scale = 0.5;
  const CelestialSphere sky(p);
  for (const auto& patch : sky.patches())
    EXPECT_DOUBLE_EQ(patch.initial_intensity, patch.band < 8 ? 0.5 : 0.25);  // C1 = 0.5, C2 = C1 / L
  EXPECT_NEAR(sky.unshaded_total(), 0.5 * 2 * pi + 0.25 * 2 * pi, 1e-12);
}

}  // namespace
}  // namespace heliostand
