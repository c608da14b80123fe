// Several hollows on one stem (issue: any tree can carry one or more): one manifold mesh without
// self-intersections whose only borders are the base ring and each cavity lip, each hollow's callus exactly as
// build_hollow() makes it alone, and clear problems when hollows cannot share the stem.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "hollow/hollow_mesh.hpp"
#include "hollow/mesh_checks.hpp"
#include "hollow/stem_mesh_builder.hpp"
#include "hollow/test_trunks.hpp"
#include "rng/random_stream.hpp"

namespace heliostand::hollow {
namespace {

// The 30 m habitat tree (radius 0.242 m at 1.5 m).
using testing::tall_trunk;

HollowSpec hollow_at(double height, double azimuth, double w = 0.12, double h = 0.20, std::uint64_t seed = 1) {
  HollowSpec s;
  s.height_m = height;
  s.azimuth_deg = azimuth;
  s.width_m = w;
  s.wound_height_m = h;
  s.seed = seed;
  return s;
}

// Callus vertices of `mesh` between two heights, sorted (to compare point sets).
std::vector<glm::dvec3> callus_between(const HollowMesh& mesh, double lo, double hi) {
  std::vector<glm::dvec3> v;
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    if (mesh.part[i] == static_cast<int>(MeshPart::callus) && mesh.vertices[i].z >= lo && mesh.vertices[i].z <= hi)
      v.push_back(mesh.vertices[i]);
  std::sort(v.begin(), v.end(), [](const glm::dvec3& a, const glm::dvec3& b) {
    return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
  });
  return v;
}

void expect_clean_stem(const std::vector<HollowSpec>& hollows, const TrunkSurface& trunk, const std::string& what) {
  ASSERT_TRUE(validate_hollows(hollows, trunk).empty()) << what << ": " << validate_hollows(hollows, trunk)[0].reason;
  const HollowMesh mesh = build_stem_with_hollows(hollows, trunk);
  const ManifoldReport m = check_manifold(mesh.vertices, mesh.triangles);
  EXPECT_EQ(m.non_manifold_edges, 0) << what;
  EXPECT_EQ(m.inconsistent_edges, 0) << what;
  EXPECT_EQ(m.degenerate_triangles, 0) << what;
  const IntersectionReport x = find_self_intersections(mesh.vertices, mesh.triangles, 3);
  EXPECT_EQ(x.count, 0) << what;
  for (const auto& pair : x.intersecting)
    ADD_FAILURE() << what << ": triangles " << pair[0] << " and " << pair[1] << " intersect near z = "
                  << mesh.vertices[mesh.triangles[pair[0]][0]].z;

  // Borders: the base ring (vertices at z = 0) and one lip edge per callus ring of each hollow; the joins
  // between the bands leave none.
  int base_ring = 0, lips = 0;
  for (const auto& v : mesh.vertices) base_ring += v.z == 0.0;
  for (const HollowSpec& spec : hollows) {
    const HollowModel alone = build_hollow(spec, trunk);
    lips += static_cast<int>(alone.callus.rings.size());
    // Each hollow's roll is in the mesh, vertex for vertex as build_hollow() makes it alone (the callus
    // depends on the hollow only; the lift of its foot on the bark patch, which is the same in a band).
    // Every hollow's callus lies in its own bark patch, and the patches are disjoint.
    const detail::PatchBounds patch = detail::patch_bounds(spec, trunk);
    const auto expected = callus_between(alone.mesh, patch.lo, patch.hi);
    const auto got = callus_between(mesh, patch.lo, patch.hi);
    ASSERT_EQ(got.size(), expected.size()) << what << ": hollow at " << spec.height_m << " m";
    ASSERT_GT(got.size(), 100u);
    for (std::size_t i = 0; i < got.size(); ++i) ASSERT_LT(glm::length(got[i] - expected[i]), 1e-12) << what;
  }
  EXPECT_EQ(m.boundary_edges, base_ring + lips) << what;

  // Every stem face points out of the wood, also in the strips that join the bands.
  int inward = 0;
  for (const auto& t : mesh.triangles) {
    const glm::dvec3 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
    if (mesh.part[t[0]] != static_cast<int>(MeshPart::trunk) || a.z > 15.0) continue;
    const glm::dvec3 centre = (a + b + c) / 3.0;
    inward += glm::dot(glm::cross(b - a, c - a), glm::dvec3(centre.x, centre.y, 0.0)) <= 0.0;
  }
  EXPECT_EQ(inward, 0) << what;
}

TEST(StackedHollows, NoHollowIsThePlainStemAndOneHollowIsBuildHollow) {
  const TrunkSurface trunk = tall_trunk();
  const HollowMesh none = build_stem_with_hollows({}, trunk), plain = build_trunk_mesh(trunk);
  EXPECT_EQ(none.vertices, plain.vertices);
  EXPECT_EQ(none.triangles, plain.triangles);
  const HollowSpec spec = hollow_at(1.5, 30.0);
  const HollowMesh one = build_stem_with_hollows({spec}, trunk), alone = build_hollow(spec, trunk).mesh;
  EXPECT_EQ(one.vertices, alone.vertices);
  EXPECT_EQ(one.triangles, alone.triangles);
}

TEST(StackedHollows, TwoHollowsOneAboveTheOtherMakeOneCleanMesh) {
  // Given in reverse height order: the builder sorts them.
  expect_clean_stem({hollow_at(2.4, 200.0, 0.16, 0.30, 2), hollow_at(1.3, 30.0)}, tall_trunk(), "two hollows");
}

TEST(StackedHollows, ThreeHollowsIncludingAWideOneAndOneAtTheRootCollar) {
  HollowSpec collar = hollow_at(0.42, 180.0, 0.22, 0.30, 3);
  collar.callus_radius_m = 0.02;
  collar.bulge_m = 0.02;
  HollowSpec wide = hollow_at(1.6, 90.0, 0.95, 0.30, 4);
  wide.callus_radius_m = 0.02;
  wide.bulge_m = 0.04;
  expect_clean_stem({collar, wide, hollow_at(6.0, 300.0)}, tall_trunk(0.6), "collar, wide and high hollows");
}

TEST(StackedHollows, SubdividedRingsAreJoinedToo) {
  // Bark lines 8 cm apart: the convexity subdivision splits the edges of the bands' edge rows too, so the join
  // must take the split rings from the mesh border, not from the grid.
  HollowSpec low = hollow_at(1.3, 0.0, 0.3, 0.3), high = hollow_at(2.2, 120.0, 0.3, 0.3, 5);
  low.callus_radius_m = high.callus_radius_m = 0.03;
  low.bark_line_spacing_m = high.bark_line_spacing_m = 0.08;
  expect_clean_stem({low, high}, tall_trunk(), "wide bark line spacing");
}

TEST(StackedHollows, TwoHollowsCloseTogetherAreJoinedAcrossANarrowGap) {
  // Default hollows (H = 0.2 m, r = 0.015 m) have patches ±0.2 m around their centres (max(H, 1.5 (H/2 + r)));
  // 0.42 m apart leaves exactly the 2 cm gap.
  expect_clean_stem({hollow_at(1.3, 0.0), hollow_at(1.7201, 180.0, 0.12, 0.20, 9)}, tall_trunk(), "2 cm gap");
}

// Pairs as close as validate_hollows allows, for sizes at the seed's extremes, both placements and a flaring
// collar (where the tangent-plane projection pushes the rim beyond ±H/2): the builder throws if a patch leaves
// the band patch_bounds() promised, and the joined mesh must be clean.
struct Pair {
  double w, h, r, i;
  Placement placement;
  double height, flare;
};

class HollowsAtTheirClosest : public ::testing::TestWithParam<Pair> {};

TEST_P(HollowsAtTheirClosest, StillMakeOneCleanMesh) {
  const Pair p = GetParam();
  const TrunkSurface trunk = tall_trunk(p.flare);
  HollowSpec low = hollow_at(p.height, 0.0, p.w, p.h, 11);
  low.callus_radius_m = p.r;
  low.bulge_m = p.i;
  low.placement = p.placement;
  HollowSpec high = low;
  high.azimuth_deg = 90.0;
  high.seed = 12;
  const double up = detail::patch_bounds(low, trunk).hi - low.height_m;
  high.height_m = low.height_m;
  const double down = low.height_m - detail::patch_bounds(high, trunk).lo;  // same size, higher: same or less flare
  high.height_m = low.height_m + up + down + min_hollow_gap_m + 1e-4;
  expect_clean_stem({low, high}, trunk,
                    fmt::format("W={} H={} r={} I={} {} at {} m, flare {}", p.w, p.h, p.r, p.i,
                                p.placement == Placement::cylindrical ? "cylindrical" : "tangent plane", p.height, p.flare));
}

INSTANTIATE_TEST_SUITE_P(SeedExtremes, HollowsAtTheirClosest,
                         ::testing::Values(Pair{0.04, 0.04, 0.01, 0.0, Placement::cylindrical, 1.5, 0.0},
                                           Pair{0.30, 0.04, 0.075, 0.0, Placement::cylindrical, 1.5, 0.0},
                                           Pair{0.04, 0.50, 0.01, 0.0, Placement::tangent_plane, 1.5, 0.0},
                                           Pair{0.25, 0.10, 0.02, 0.04, Placement::tangent_plane, 1.5, 0.0},
                                           Pair{0.20, 0.30, 0.02, 0.02, Placement::tangent_plane, 0.42, 0.6},
                                           Pair{0.20, 0.25, 0.02, 0.02, Placement::cylindrical, 0.35, 0.5}));

// Random stacks (fixed seed): 2-4 hollows of random size, placement and height on stems with and without a
// collar; those validate_hollows accepts must build clean. (Run by hand with 25 stacks: all clean.)
TEST(StackedHollows, RandomStacksThatValidateBuildClean) {
  RandomStream rng(2024, {0x53544bULL /* "STK" */});
  int built = 0;
  for (int trial = 0; trial < 40 && built < 5; ++trial) {
    const TrunkSurface trunk = TrunkSurface::seed001_taper(rng.uniform(20.0, 30.0), 10.0,
                                                           {rng.uniform(0.0, 1.0) < 0.3 ? 0.6 : 0.0, 0.3});
    std::vector<HollowSpec> hollows(2 + static_cast<int>(rng.uniform(0.0, 2.999)));
    for (std::size_t i = 0; i < hollows.size(); ++i) {
      HollowSpec& s = hollows[i];
      s.width_m = rng.uniform(0.04, 0.34);
      s.wound_height_m = rng.uniform(0.04, 0.44);
      s.callus_radius_m = rng.uniform(0.01, s.width_m / 4.0);
      s.bulge_m = rng.uniform(0.0, s.width_m / 4.0 - s.callus_radius_m);
      s.height_m = rng.uniform(0.3, 6.3);
      s.azimuth_deg = rng.uniform(0.0, 360.0);
      s.placement = rng.uniform(0.0, 1.0) < 0.3 ? Placement::tangent_plane : Placement::cylindrical;
      s.seed = 100 * trial + i;
    }
    if (!validate_hollows(hollows, trunk).empty()) continue;
    ++built;
    expect_clean_stem(hollows, trunk, fmt::format("random stack {} ({} hollows)", trial, hollows.size()));
  }
  EXPECT_EQ(built, 5);
}

TEST(StackedHollows, OverlappingHollowsAreRejectedWithTheGapTheyNeed) {
  const TrunkSurface trunk = tall_trunk();
  // Hand-computed: patch half-height max(0.2, 1.5 · (0.1 + 0.015)) = 0.2 m each, plus the 2 cm gap.
  EXPECT_TRUE(validate_hollows({hollow_at(1.3, 0.0), hollow_at(1.721, 0.0)}, trunk).empty());
  const auto close = validate_hollows({hollow_at(1.3, 0.0), hollow_at(1.7, 0.0)}, trunk);
  ASSERT_EQ(close.size(), 1u);
  EXPECT_EQ(close[0].field, "hollows[1].height_m");
  EXPECT_NE(close[0].reason.find("hollows[0]"), std::string::npos) << close[0].reason;
  EXPECT_NE(close[0].reason.find("at least 0.420 m apart, got 0.400 m"), std::string::npos) << close[0].reason;

  // Side by side at one height: the later one is named, and the reason says why.
  const auto side_by_side = validate_hollows({hollow_at(1.5, 0.0), hollow_at(1.5, 180.0)}, trunk);
  ASSERT_EQ(side_by_side.size(), 1u);
  EXPECT_EQ(side_by_side[0].field, "hollows[1].height_m");
  EXPECT_NE(side_by_side[0].reason.find("side by side"), std::string::npos) << side_by_side[0].reason;

  // Listed in any order: the upper hollow is the one named.
  const auto reversed = validate_hollows({hollow_at(1.7, 0.0), hollow_at(1.3, 0.0)}, trunk);
  ASSERT_EQ(reversed.size(), 1u);
  EXPECT_EQ(reversed[0].field, "hollows[0].height_m");
  EXPECT_NE(reversed[0].reason.find("hollows[1]"), std::string::npos) << reversed[0].reason;
}

TEST(StackedHollows, EachHollowsOwnProblemsNameItsIndex) {
  const TrunkSurface trunk = tall_trunk();
  HollowSpec bad = hollow_at(3.0, 0.0);
  bad.width_m = 0.01;
  const auto problems = validate_hollows({hollow_at(1.3, 0.0), bad}, trunk);
  ASSERT_FALSE(problems.empty());
  EXPECT_EQ(problems[0].field, "hollows[1].width_m");
  try {
    build_stem_with_hollows({hollow_at(1.3, 0.0), hollow_at(1.4, 90.0)}, trunk);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("field 'hollows[1].height_m'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace heliostand::hollow
