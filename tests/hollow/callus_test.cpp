// Seed 004 eqs. 3.9–3.11: callus polygons, their jitter, the vertical bulge, and the crossing limit we add.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include <glm/geometric.hpp>

#include "geometry/angles.hpp"
#include "hollow/callus.hpp"
#include "hollow/hollow_mesh.hpp"
#include "hollow/placement.hpp"
#include "hollow/test_trunks.hpp"
#include "hollow/wound_outline.hpp"
#include "rng/random_stream.hpp"

namespace heliostand::hollow {
namespace {

using testing::short_trunk;

TEST(CallusJitter, AnglesStayWithinFiveDegreesSumToZeroAndKeepTheirOrder) {
  RandomStream rng(3, {1});
  for (int corners : {4, 8, 12, 36}) {
    for (int draw = 0; draw < 200; ++draw) {
      const std::vector<double> c = corner_angle_jitter(corners, rng);
      ASSERT_EQ(static_cast<int>(c.size()), corners);
      EXPECT_EQ(c[0], 0.0);
      EXPECT_NEAR(std::accumulate(c.begin(), c.end(), 0.0), 0.0, 1e-12);
      for (int m = 0; m < corners; ++m) {
        EXPECT_LE(std::abs(c[m]), radians(5.0) + 1e-12);
        if (m > 0) EXPECT_GE(m * 2 * pi / corners + c[m], (m - 1) * 2 * pi / corners + c[m - 1]);
      }
    }
  }
}

Callus callus_for(const HollowSpec& spec, const TrunkSurface& trunk, bool limits = true) {
  const StemChart chart(trunk, spec.height_m, radians(spec.azimuth_deg));
  const auto outline = place_outline(sample_outline(spec.width_m, spec.wound_height_m, spec.outline_step_m),
                                     chart, spec.placement);
  return build_callus(outline, chart, spec, limits);
}

// Mean height of the roll's top corners (θ near 90°) off the stem where the rim runs vertically vs horizontally.
std::pair<double, double> thickness_vertical_horizontal(const Callus& callus) {
  double vertical = 0, horizontal = 0;
  int nv = 0, nh = 0;
  const int n = static_cast<int>(callus.rings.size());
  for (int j = 0; j < n; ++j) {
    const CallusRing& ring = callus.rings[j];
    const double slope = std::abs(ring.axis.z);
    const double top = ring.radius[2];  // θ_2 = 90° ± 5° for M = 8
    if (slope > 0.95) vertical += top, ++nv;
    if (slope < 0.2) horizontal += top, ++nh;
  }
  return {vertical / nv, horizontal / nh};
}

TEST(Callus, VerticalRimStretchesSwellMoreThanHorizontalOnes) {
  const TrunkSurface trunk = short_trunk();
  HollowSpec spec;  // W = 0.12, H = 0.20, r = 0.015, I = 0.01
  const auto [vertical, horizontal] = thickness_vertical_horizontal(callus_for(spec, trunk));
  // E_j ≈ I on vertical stretches and ≈ 0 on horizontal ones: 0.015 + 0.01 vs 0.015 (± 10 % jitter).
  EXPECT_NEAR(vertical, 0.025, 0.0025);
  EXPECT_NEAR(horizontal, 0.015, 0.0025);
  EXPECT_GT(vertical, 1.4 * horizontal);
  // Without the bulge both are r (the jitter averages out).
  spec.bulge_m = 0.0;
  const auto [v0, h0] = thickness_vertical_horizontal(callus_for(spec, trunk));
  EXPECT_NEAR(v0 / h0, 1.0, 0.08);
}

TEST(Callus, CornerRadiiAreRTimesAJitterBetweenPointNineAndOnePointOne) {
  const TrunkSurface trunk = short_trunk();
  HollowSpec spec;
  spec.bulge_m = 0.0;
  spec.width_m = 0.2;
  spec.wound_height_m = 0.3;
  const Callus callus = callus_for(spec, trunk, /*limits=*/false);
  double lo = 1e9, hi = 0;
  for (const auto& ring : callus.rings)
    for (std::size_t m = 1; m < ring.radius.size(); ++m) lo = std::min(lo, ring.radius[m]), hi = std::max(hi, ring.radius[m]);
  EXPECT_GE(lo, 0.9 * spec.callus_radius_m - 1e-12);
  EXPECT_LE(hi, 1.1 * spec.callus_radius_m + 1e-12);
  EXPECT_LT(lo, 0.92 * spec.callus_radius_m);  // the whole range is used
  EXPECT_GT(hi, 1.08 * spec.callus_radius_m);
}

TEST(Callus, CornersSitOnTheirPolygonPlaneAroundTheRim) {
  const TrunkSurface trunk = short_trunk();
  const Callus callus = callus_for(HollowSpec{}, trunk);
  for (std::size_t j = 0; j < callus.rings.size(); j += 37) {
    const CallusRing& ring = callus.rings[j];
    for (std::size_t m = 1; m < ring.corners.size(); ++m)
      EXPECT_NEAR(glm::dot(ring.corners[m] - ring.centre, ring.axis), 0.0, 1e-9);
    // The foot is placed in the stem chart (where the bark meets it), so it is in the plane only up to the
    // chart's distortion over one callus radius.
    EXPECT_NEAR(glm::dot(ring.corners[0] - ring.centre, ring.axis), 0.0, 0.01 * ring.radius[0]);
    // Corner 2 (θ ≈ 90°) stands off the stem, corner 6 (θ ≈ 270°) points into the wood.
    EXPECT_GT(trunk.outside(ring.corners[2]), 0.5 * ring.radius[2]);
    EXPECT_LT(trunk.outside(ring.corners[6]), -0.5 * ring.radius[6]);
  }
}

int band_crossings(Callus callus) { return separate_polygons(callus, 0); }

TEST(Callus, ThickCallusOnASlenderWoundNoLongerCrossesItself) {
  // The seed's limit: on a narrow, tall wound a thick roll makes neighbouring polygons cross at the apexes.
  const TrunkSurface trunk = short_trunk();
  HollowSpec spec;
  spec.width_m = 0.06;
  spec.wound_height_m = 0.40;
  spec.callus_radius_m = 0.01;
  spec.bulge_m = 0.005;  // I = W/4 − r, the largest the seed allows
  const Callus seed = callus_for(spec, trunk, /*limits=*/false);
  EXPECT_GT(band_crossings(seed), 0);
  const Callus ours = callus_for(spec, trunk);
  EXPECT_EQ(band_crossings(ours), 0);
  // Only the apexes are thinned: most of the roll keeps its full size.
  int untouched = 0;
  for (const auto& ring : ours.rings) untouched += ring.limit_scale > 0.999;
  EXPECT_GT(untouched, static_cast<int>(ours.rings.size()) / 2);
}

TEST(Callus, ButtressThickensTheRollNearTheRootCollar) {
  const TrunkSurface plain = TrunkSurface::seed001_taper(20.0, 10.0);
  const TrunkSurface flared = TrunkSurface::seed001_taper(20.0, 10.0, {0.6, 0.3});
  HollowSpec spec;
  spec.height_m = 0.25;
  spec.wound_height_m = 0.16;
  spec.width_m = 0.12;
  spec.bulge_m = 0.0;
  // Same seed, same jitter: the roll on the flared collar is the plain one scaled by 1 + 0.6 e^(−h/0.3).
  const Callus on_plain = callus_for(spec, plain, /*limits=*/false);
  const Callus on_flare = callus_for(spec, flared, /*limits=*/false);
  ASSERT_EQ(on_plain.rings.size(), on_flare.rings.size());
  for (std::size_t j = 0; j < on_flare.rings.size(); j += 29) {
    const double h = on_flare.rings[j].centre.z;
    const double flare = 1.0 + 0.6 * std::exp(-h / 0.3);
    EXPECT_NEAR(on_flare.rings[j].flare, flare, 1e-9);
    EXPECT_NEAR(on_flare.rings[j].radius[2] / on_plain.rings[j].radius[2], flare, 0.01 * flare) << j;
  }
  // So the roll thickens towards the ground: the lowest ring is thicker than the highest.
  const Callus limited = callus_for(spec, flared);
  double lowest = 1e9, highest = -1e9, r_low = 0, r_high = 0;
  for (const auto& ring : limited.rings) {
    if (ring.centre.z < lowest) lowest = ring.centre.z, r_low = ring.radius[2];
    if (ring.centre.z > highest) highest = ring.centre.z, r_high = ring.radius[2];
  }
  EXPECT_GT(r_low, 1.1 * r_high);
}

}  // namespace
}  // namespace heliostand::hollow
