// A hollow all around a broken stem: the rim of the break carries the roll, the bark runs straight into it.
#include <gtest/gtest.h>

#include <cmath>

#include "hollow/broken_stem.hpp"
#include "hollow/mesh_checks.hpp"
#include "hollow/test_trunks.hpp"

namespace heliostand::hollow {
namespace {

using testing::tall_trunk;

void expect_clean(const HollowModel& model, const std::string& what) {
  const ManifoldReport m = check_manifold(model.mesh.vertices, model.mesh.triangles);
  EXPECT_EQ(m.non_manifold_edges, 0) << what;
  EXPECT_EQ(m.inconsistent_edges, 0) << what;
  EXPECT_EQ(m.degenerate_triangles, 0) << what;
  // Borders: the stem's base ring and the roll's lip inside the broken stem, nothing else.
  int base = 0;
  for (const auto& v : model.mesh.vertices) base += v.z == 0.0;
  EXPECT_EQ(m.boundary_edges, base + static_cast<int>(model.callus.rings.size())) << what;
  EXPECT_EQ(find_self_intersections(model.mesh.vertices, model.mesh.triangles).count, 0) << what;
}

TEST(BrokenStem, RollRunsAllAroundTheRimWithoutSelfIntersections) {
  const TrunkSurface trunk = tall_trunk();
  for (double tilt : {0.0, 0.15, 0.4}) {
    BrokenStemSpec spec;
    spec.break_height_m = 4.0;
    spec.break_tilt_m = tilt;
    spec.callus_radius_m = 0.03;
    spec.bulge_m = 0.02;
    const HollowModel model = build_broken_stem(spec, trunk);
    expect_clean(model, "tilt " + std::to_string(tilt));
    // The rim goes once around: its polygons' centres cover every direction.
    double lo = 1e9, hi = -1e9;
    for (const auto& v : model.outline_xy) lo = std::min(lo, v.x), hi = std::max(hi, v.x);
    EXPECT_GT((hi - lo) / model.chart_radius, 2.0 * 3.14159 * 0.999);
  }
}

TEST(BrokenStem, RollIsThickestWhereTheObliqueRimRunsSteepest) {
  BrokenStemSpec spec;
  spec.break_height_m = 4.0;
  spec.break_tilt_m = 0.4;  // rim height (tilt/2)·cos(x/ρ): level at the front and back, steepest at the sides
  spec.callus_radius_m = 0.02;
  spec.bulge_m = 0.03;
  const HollowModel model = build_broken_stem(spec, tall_trunk());
  double level = 0, steep = 0;
  int nl = 0, ns = 0;
  for (const auto& ring : model.callus.rings) {
    const double angle = std::abs(ring.centre_xy.x / model.chart_radius);  // 0 at the front, π at the back
    if (angle < 0.1 || angle > 3.04) level += ring.radius[2], ++nl;
    if (std::abs(angle - 1.5708) < 0.1) steep += ring.radius[2], ++ns;
  }
  // Steepest slope of the rim: (tilt/2)/ρ ≈ 0.2/0.23, so |F̂·z| ≈ 0.66 and E ≈ 0.66 I there, 0 where level.
  EXPECT_GT(steep / ns, level / nl + 0.5 * 0.66 * spec.bulge_m);
}

TEST(BrokenStem, BarkLinesRunStraightIntoTheRoll) {
  BrokenStemSpec spec;
  const HollowModel model = build_broken_stem(spec, tall_trunk());
  for (std::size_t c = 0; c < model.bark.x.size(); ++c)
    for (double X : model.bark.X[c]) EXPECT_DOUBLE_EQ(X, model.bark.x[c]);
}

TEST(BrokenStem, InvalidBreaksAreRejectedWithTheFieldNamed) {
  const TrunkSurface trunk = tall_trunk();
  BrokenStemSpec spec;
  spec.break_height_m = 29.0;
  ASSERT_FALSE(validate(spec, trunk).empty());
  EXPECT_EQ(validate(spec, trunk)[0].field, "break_height_m");
  spec = {};
  spec.callus_radius_m = 0.2;
  EXPECT_EQ(validate(spec, trunk)[0].field, "callus_radius_m");
  spec = {};
  spec.break_tilt_m = -0.1;
  EXPECT_EQ(validate(spec, trunk)[0].field, "break_tilt_m");
  spec = {};
  spec.bulge_m = 0.5;
  EXPECT_EQ(validate(spec, trunk)[0].field, "bulge_m");
  EXPECT_THROW(build_broken_stem(spec, trunk), InputError);
}

}  // namespace
}  // namespace heliostand::hollow
