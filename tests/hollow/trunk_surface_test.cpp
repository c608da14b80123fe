// The stem surface: seed 001 eq. 2 taper, the root-collar flare, the seed-004 placement helpers.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "hollow/placement.hpp"
#include "hollow/trunk_surface.hpp"

namespace heliostand::hollow {
namespace {

TEST(TrunkSurface, Seed001TaperGivesEquation2Diameters) {
  const TrunkSurface trunk = TrunkSurface::seed001_taper(20.0, 10.0);
  // In the crown, h = 15: d = 2.245 · 5^0.951 cm; 5^0.951 = e^(0.951 · 1.6094379) = e^1.5305754 = 4.6209
  // → d = 10.374 cm.
  EXPECT_NEAR(trunk.radius(15.0), 0.10374 / 2.0, 1e-5);
  // Below the crown the fit is scaled to meet the crown fit at the crown base (h = 10, depth 10):
  // 2.245 · 10^0.951 = 20.055 cm and 3.336 · 10^0.771 = 19.689 cm → factor 1.01857.
  // h = 5: 3.336 · 15^0.771 = 3.336 · e^(0.771 · 2.7080502) = 3.336 · 8.0680 = 26.915 cm → × 1.01857 = 27.415 cm.
  EXPECT_NEAR(trunk.radius(5.0), 0.27415 / 2.0, 2e-5);
  EXPECT_NEAR(trunk.radius(10.0 - 1e-9), trunk.radius(10.0), 1e-9);  // no step at the crown base
  EXPECT_DOUBLE_EQ(trunk.radius(20.0), 0.0);
}

TEST(TrunkSurface, ButtressWidensTheCollarAndFadesWithHeight) {
  const TrunkSurface plain = TrunkSurface::seed001_taper(20.0, 10.0);
  const TrunkSurface flared = TrunkSurface::seed001_taper(20.0, 10.0, {0.5, 0.3});
  EXPECT_NEAR(flared.radius(0.0), 1.5 * plain.radius(0.0), 1e-12);
  EXPECT_NEAR(flared.flare_factor(0.3), 1.0 + 0.5 / std::exp(1.0), 1e-12);
  EXPECT_NEAR(flared.radius(3.0), plain.radius(3.0), 1e-4 * plain.radius(3.0));
  // The collar slopes outwards going down: the normal tilts upward there.
  EXPECT_GT(flared.outward_normal(0.1, 0.0).z, 0.2);
}

TEST(TrunkSurface, CrossSurfaceFindsTheStemAlongARay) {
  const TrunkSurface trunk([](double) { return 0.2; }, 10.0);
  const glm::dvec3 hit = trunk.cross_surface({0, 0, 1}, {1, 1, 1});
  EXPECT_NEAR(std::hypot(hit.x, hit.y), 0.2, 1e-9);
  EXPECT_NEAR(hit.x, hit.y, 1e-9);
}

TEST(TangentPlanePlacement, PlaneFacesOutAlongLAndKeepsItsVerticalAxisUp) {
  const TrunkSurface trunk([](double) { return 0.2; }, 10.0);
  const StemChart chart(trunk, 1.5, 0.5 * 3.141592653589793);  // facing north (+y)
  const TangentPlaneFrame frame = tangent_plane_frame(chart);
  EXPECT_NEAR(glm::length(frame.a_point - glm::dvec3(0, 0.2, 1.5)), 0.0, 1e-9);  // A on the front
  EXPECT_NEAR(glm::length(frame.b_point - glm::dvec3(0, 0, 1.5)), 0.0, 1e-9);    // B on the axis
  EXPECT_NEAR(glm::length(frame.y_axis - glm::dvec3(0, 0, 1)), 0.0, 1e-12);
  // x′ runs counter-clockwise seen from above (−x when facing north), like the chart's x.
  EXPECT_NEAR(glm::length(frame.x_axis - glm::dvec3(-1, 0, 0)), 0.0, 1e-12);
  // A plane point 0.2 m across projects from B to 45° around the stem: chart x = ρ·π/4.
  const glm::dvec2 xy = chart.chart_of(frame.project({0.2, 0.0}, trunk));
  EXPECT_NEAR(xy.x, 0.2 * 3.141592653589793 / 4.0, 1e-6);
  EXPECT_NEAR(xy.y, 0.0, 1e-9);
}

}  // namespace
}  // namespace heliostand::hollow
