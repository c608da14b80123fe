// The assembled hollow mesh: manifold, consistently oriented, free of self-intersections, for a sweep of
// W, H, r, I including the extremes the seed allows, in both placements; and the seed's limits lifted:
// wider than half the stem, bark following the stem's convexity, hollows at the root collar.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "geometry/angles.hpp"
#include "hollow/hollow_mesh.hpp"
#include "hollow/mesh_checks.hpp"
#include "hollow/test_trunks.hpp"

namespace heliostand::hollow {
namespace {

// A 30 m habitat tree (Todomatsu taper, seed 001 eq. 2, crown base at 15 m): radius 0.242 m at 1.5 m
// (circumference 1.52 m).
using testing::tall_trunk;

struct Case {
  double w, h, r, i;
  Placement placement = Placement::cylindrical;
  double height = 1.5;
  double flare = 0.0;
};

std::string describe(const Case& c) {
  return fmt::format("W={} H={} r={} I={} {} at {} m flare {}", c.w, c.h, c.r, c.i,
                     c.placement == Placement::cylindrical ? "cylindrical" : "tangent-plane", c.height, c.flare);
}

HollowSpec spec_for(const Case& c) {
  HollowSpec s;
  s.width_m = c.w;
  s.wound_height_m = c.h;
  s.callus_radius_m = c.r;
  s.bulge_m = c.i;
  s.placement = c.placement;
  s.height_m = c.height;
  s.azimuth_deg = 30.0;
  s.seed = 7;
  return s;
}

void expect_clean(const HollowMesh& mesh, const std::string& what) {
  const ManifoldReport m = check_manifold(mesh.vertices, mesh.triangles);
  EXPECT_EQ(m.non_manifold_edges, 0) << what;
  EXPECT_EQ(m.inconsistent_edges, 0) << what;
  EXPECT_EQ(m.degenerate_triangles, 0) << what;
  const IntersectionReport x = find_self_intersections(mesh.vertices, mesh.triangles, 1);
  EXPECT_EQ(x.count, 0) << what << " (" << x.pairs_tested << " pairs tested)";
  for (const auto& pair : x.intersecting) {
    auto parts = [&](int t) {
      const auto& tri = mesh.triangles[t];
      return fmt::format("{}{}{}", mesh.part[tri[0]], mesh.part[tri[1]], mesh.part[tri[2]]);
    };
    ADD_FAILURE() << what << ": triangles " << pair[0] << " (parts " << parts(pair[0]) << ") and " << pair[1]
                  << " (parts " << parts(pair[1]) << ") intersect near z = "
                  << mesh.vertices[mesh.triangles[pair[0]][0]].z;
  }
}

// Boundary edges the mesh should have: the stem's base ring, the cavity lip and nothing else.
void expect_only_intended_borders(const HollowModel& model, const std::string& what) {
  const ManifoldReport m = check_manifold(model.mesh.vertices, model.mesh.triangles);
  const int rings = static_cast<int>(model.callus.rings.size());
  int base_ring = 0;
  for (const auto& v : model.mesh.vertices) base_ring += v.z == 0.0;
  EXPECT_EQ(m.boundary_edges, rings + base_ring) << what;
}

class HollowSweep : public ::testing::TestWithParam<Case> {};

// Test names like W120_H200_r015_I010_cylindrical_h150 (sizes in mm, height in cm).
std::string case_name(const ::testing::TestParamInfo<Case>& info) {
  const Case& c = info.param;
  auto mm = [](double m) { return static_cast<int>(std::lround(m * 1000)); };
  return fmt::format("W{}_H{}_r{}_I{}_{}_h{}_flare{}", mm(c.w), mm(c.h), mm(c.r), mm(c.i),
                     c.placement == Placement::cylindrical ? "cylindrical" : "tangent", mm(c.height) / 10,
                     static_cast<int>(std::lround(c.flare * 10)));
}

void PrintTo(const Case& c, std::ostream* os) { *os << describe(c); }

TEST_P(HollowSweep, MeshIsManifoldConsistentAndFreeOfSelfIntersections) {
  const Case c = GetParam();
  const TrunkSurface trunk = tall_trunk(c.flare);
  const HollowSpec spec = spec_for(c);
  ASSERT_TRUE(validate(spec, trunk).empty()) << describe(c) << ": " << validate(spec, trunk)[0].reason;
  const HollowModel model = build_hollow(spec, trunk);
  expect_clean(model.mesh, describe(c));
  expect_only_intended_borders(model, describe(c));
}

// W and H at the seed's minimum (4 units = 4 cm) and well beyond; r at its limits 1 unit and W/4; I at 0 and at
// its limit W/4 − r.
std::vector<Case> sweep() {
  std::vector<Case> cases;
  for (double w : {0.04, 0.12, 0.30})
    for (double h : {0.04, 0.20, 0.50})
      for (bool thick : {false, true})
        for (bool bulge : {false, true}) {
          const double r = thick ? w / 4.0 : 0.01;
          const double i = bulge ? w / 4.0 - r : 0.0;
          const bool seen = std::any_of(cases.begin(), cases.end(), [&](const Case& c) {
            return c.w == w && c.h == h && c.r == r && c.i == i;  // e.g. W = 0.04: r = W/4 = 1 cm, I = 0
          });
          if (!seen) cases.push_back({w, h, r, i});
        }
  // The seed's own placement, within its limit (narrower than the stem).
  cases.push_back({0.12, 0.20, 0.015, 0.01, Placement::tangent_plane});
  cases.push_back({0.25, 0.10, 0.02, 0.04, Placement::tangent_plane});
  cases.push_back({0.04, 0.50, 0.01, 0.0, Placement::tangent_plane});
  return cases;
}

INSTANTIATE_TEST_SUITE_P(SeedRanges, HollowSweep, ::testing::ValuesIn(sweep()), case_name);

// Beyond the seed: wider than half the circumference (0.6 m = 39 %, 0.9 m = 59 %, 1.4 m = 92 % of the
// 1.52 m circumference, measured along the rim's widest chord W), and at the root collar.
INSTANTIATE_TEST_SUITE_P(BeyondTheSeed, HollowSweep,
                         ::testing::Values(Case{0.60, 0.30, 0.02, 0.05}, Case{0.90, 0.30, 0.02, 0.05},
                                           Case{1.40, 0.20, 0.015, 0.0}, Case{0.20, 0.25, 0.02, 0.02, Placement::cylindrical, 0.35, 0.5},
                                           Case{0.30, 0.30, 0.03, 0.03, Placement::cylindrical, 0.42, 0.8}),
                         case_name);

TEST(HollowMesh, WiderThanHalfTheStemOnlyWithCylindricalPlacement) {
  const TrunkSurface trunk = tall_trunk();
  const double circumference = 2.0 * pi * trunk.radius(1.5);
  HollowSpec spec = spec_for({0.85 * circumference, 0.3, 0.02, 0.05});
  ASSERT_TRUE(validate(spec, trunk).empty());
  const HollowModel model = build_hollow(spec, trunk);
  // The wound really wraps: its rim spans more than half the stem's angle (chart x is arc length at ρ0).
  double left = 0, right = 0;
  for (const auto& v : model.outline_xy) left = std::min(left, v.x), right = std::max(right, v.x);
  EXPECT_GT((right - left) / model.chart_radius, pi);
  spec.placement = Placement::tangent_plane;
  const auto problems = validate(spec, trunk);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].field, "width_m");
}

// Depth of the deepest point (edge midpoints and centroids) of stem/bark faces below the stem surface.
double deepest_cut(const HollowMesh& mesh, const TrunkSurface& trunk) {
  double deepest = 0.0;
  for (const auto& t : mesh.triangles) {
    bool stem = true;
    for (int v : t) stem = stem && mesh.part[v] != static_cast<int>(MeshPart::callus);
    if (!stem) continue;
    const glm::dvec3 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
    for (const glm::dvec3& p : {(a + b) / 2.0, (b + c) / 2.0, (c + a) / 2.0, (a + b + c) / 3.0})
      if (p.z < trunk.tree_height() * 0.9) deepest = std::max(deepest, -trunk.outside(p));
  }
  return deepest;
}

TEST(HollowMesh, BarkFacesFollowTheStemsConvexityWithinTheTolerance) {
  // Widely spaced bark lines (l = 8 cm on a 0.242 m radius stem) are the seed's worst case: flat faces between
  // lines cut into the stem by up to ρ(1 − cos(l/2ρ)) = 0.242 · (1 − cos 0.165) ≈ 3.3 mm.
  const TrunkSurface trunk = tall_trunk();
  HollowSpec spec = spec_for({0.3, 0.3, 0.03, 0.04});
  spec.bark_line_spacing_m = 0.08;
  spec.surface_tolerance_m = 0.0005;
  BuildOptions seed_like;
  seed_like.follow_convexity = false;
  const HollowModel flat = build_hollow(spec, trunk, seed_like);
  EXPECT_GT(deepest_cut(flat.mesh, trunk), 0.0025);
  const HollowModel ours = build_hollow(spec, trunk);
  EXPECT_GT(ours.refinement_passes, 0);
  EXPECT_LT(deepest_cut(ours.mesh, trunk), spec.surface_tolerance_m);
  expect_clean(ours.mesh, "refined wide bark lines");
}

struct FlankThickness {
  double low = 0, high = 0, flare_low = 0, flare_high = 0;
};

// Mean top-corner radius and flare of the rings on the lower and upper flanks of the wound (rim running
// vertically, so both get the full bulge E_j).
FlankThickness flank_thickness(const HollowModel& model) {
  FlankThickness f;
  int nl = 0, nh = 0;
  for (const auto& ring : model.callus.rings) {
    if (std::abs(ring.axis.z) < 0.9) continue;
    if (ring.centre_xy.y < -0.05) f.low += ring.radius[2], f.flare_low += ring.flare, ++nl;
    if (ring.centre_xy.y > 0.05) f.high += ring.radius[2], f.flare_high += ring.flare, ++nh;
  }
  EXPECT_GT(nl, 10);
  EXPECT_GT(nh, 10);
  f.low /= nl, f.flare_low /= nl, f.high /= nh, f.flare_high /= nh;
  return f;
}

TEST(HollowMesh, RootCollarHollowHasAThickerCallusAtItsFoot) {
  const HollowSpec spec = spec_for({0.2, 0.3, 0.02, 0.02, Placement::cylindrical, 0.4});
  const HollowModel flared = build_hollow(spec, tall_trunk(0.6));
  const HollowModel plain = build_hollow(spec, tall_trunk(0.0));
  const FlankThickness f = flank_thickness(flared), p = flank_thickness(plain);
  // The flare 1 + 0.6 e^(−h/0.3) is about 1.22 on the lower flank (h ≈ 0.3 m) and 1.12 on the upper (h ≈ 0.5 m).
  EXPECT_GT(f.flare_low, 1.05 * f.flare_high);
  EXPECT_DOUBLE_EQ(p.flare_low, 1.0);
  // The outline's own shape makes the flanks differ a little on a plain stem; on the collar the lower flank
  // gains at least the flare ratio (the exact scaling by the flare is checked in callus_test.cpp, without
  // the crossing limits, which also react to the wider stem).
  EXPECT_GT((f.low / f.high) / (p.low / p.high), f.flare_low / f.flare_high - 0.01);
  expect_clean(flared.mesh, "root collar");
}

TEST(HollowMesh, SameSeedSameMeshOtherSeedOtherJitter) {
  const TrunkSurface trunk = tall_trunk();
  HollowSpec spec;
  const HollowModel a = build_hollow(spec, trunk), b = build_hollow(spec, trunk);
  ASSERT_EQ(a.mesh.vertices.size(), b.mesh.vertices.size());
  for (std::size_t v = 0; v < a.mesh.vertices.size(); ++v) ASSERT_EQ(a.mesh.vertices[v], b.mesh.vertices[v]);
  spec.seed = 99;
  const HollowModel c = build_hollow(spec, trunk);
  EXPECT_NE(a.callus.rings[10].radius[3], c.callus.rings[10].radius[3]);
}

TEST(HollowMesh, FacesPointOutOfTheWood) {
  const TrunkSurface trunk = tall_trunk();
  const HollowModel model = build_hollow(HollowSpec{}, trunk);
  int outward = 0, stem_faces = 0;
  for (const auto& t : model.mesh.triangles) {
    const glm::dvec3 a = model.mesh.vertices[t[0]], b = model.mesh.vertices[t[1]], c = model.mesh.vertices[t[2]];
    if (model.mesh.part[t[0]] != static_cast<int>(MeshPart::trunk) || a.z > 15.0) continue;
    const glm::dvec3 centre = (a + b + c) / 3.0;
    ++stem_faces;
    outward += glm::dot(glm::cross(b - a, c - a), glm::dvec3(centre.x, centre.y, 0.0)) > 0.0;
  }
  EXPECT_EQ(outward, stem_faces);
}

TEST(HollowMesh, InvalidSpecIsRejectedWithTheFieldNamed) {
  const TrunkSurface trunk = tall_trunk();
  HollowSpec spec;
  spec.callus_radius_m = -1;
  try {
    build_hollow(spec, trunk);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("field 'callus_radius_m'"), std::string::npos) << e.what();
  }
}

// The slenderest wound the seed allows, placed by the tangent plane: the across-the-wound clearance squeezes
// the polygons beside the bottom apex, and before the radius floor (callus.cpp, min_squeezed_radius) seeds 4,
// 6, 9, 11, 14 and 16 left polygons of ~0.1 µm whose roll triangles touched (found while testing stacked
// hollows; seeds 1-16 at azimuths 0° and 90° checked, the others were clean).
TEST(HollowMesh, SlenderTangentPlaneWoundKeepsItsApexCleanForEverySeed) {
  HollowSpec spec = spec_for({0.04, 0.50, 0.01, 0.0, Placement::tangent_plane});
  spec.azimuth_deg = 0.0;
  for (std::uint64_t seed : {4, 6, 9, 11, 14, 16}) {
    spec.seed = seed;
    expect_clean(build_hollow(spec, tall_trunk()).mesh, fmt::format("W 4 cm, H 50 cm, tangent plane, seed {}", seed));
  }
}

TEST(TrunkMesh, PlainStemIsManifoldAndWithinToleranceOfTheTaper) {
  const TrunkSurface trunk = tall_trunk(0.5);
  const HollowMesh mesh = build_trunk_mesh(trunk, 0.0005);
  expect_clean(mesh, "plain stem");
  EXPECT_LT(deepest_cut(mesh, trunk), 0.0006);
}

}  // namespace
}  // namespace heliostand::hollow
