// Seed 004 §3.2: bark lines deflect around the wound, push their neighbours with a push that decays away from
// the wound, return to their original spacing far from it, and rise near the wound (eq. 3.18).
#include <gtest/gtest.h>

#include <cmath>

#include "hollow/bark_flow.hpp"
#include "hollow/hollow_mesh.hpp"

namespace heliostand::hollow {
namespace {

HollowModel default_model() {
  static const TrunkSurface trunk = TrunkSurface::seed001_taper(20.0, 10.0);
  static const HollowModel model = build_hollow(HollowSpec{}, trunk);
  return model;
}

bool inside(const std::vector<glm::dvec2>& loop, glm::dvec2 p) {
  bool in = false;
  for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
    const auto& a = loop[i];
    const auto& b = loop[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

TEST(BarkFlow, LinesLeftOfTheSplitFlowLeftTheOthersRight) {
  const BarkLines& lines = default_model().bark;
  int moved = 0;
  for (std::size_t c = 0; c < lines.x.size(); ++c) {
    for (std::size_t k = 0; k < lines.y.size(); ++k) {
      const double shift = lines.X[c][k] - lines.x[c];
      if (static_cast<int>(c) == lines.split_column || std::isnan(shift)) continue;
      if (lines.x[c] < 0) EXPECT_LE(shift, 0.0);
      if (lines.x[c] > 0) EXPECT_GE(shift, 0.0);
      moved += std::abs(shift) > 1e-6;
    }
  }
  EXPECT_GT(moved, 100);
}

TEST(BarkFlow, NoBarkLineVertexIsLeftInsideTheCallusFoot) {
  const HollowModel model = default_model();
  std::vector<glm::dvec2> foot;
  for (const auto& ring : model.callus.rings) foot.push_back(ring.foot_xy);
  const BarkLines& lines = model.bark;
  int checked = 0;
  for (std::size_t c = 0; c < lines.x.size(); ++c)
    for (std::size_t k = 0; k < lines.y.size(); ++k) {
      if (std::isnan(lines.X[c][k])) continue;
      EXPECT_FALSE(inside(foot, {lines.X[c][k], lines.y[k]})) << "line " << c << " row " << k;
      ++checked;
    }
  EXPECT_GT(checked, 1000);
  // … while undisplaced, the lines near the split would cross the wound.
  int would_be_inside = 0;
  for (std::size_t c = 0; c < lines.x.size(); ++c)
    for (double y : lines.y) would_be_inside += inside(foot, {lines.x[c], y});
  EXPECT_GT(would_be_inside, 50);
}

TEST(BarkFlow, PushDecaysWithDistanceFromTheWoundAndLinesKeepTheirOrder) {
  const BarkLines& lines = default_model().bark;
  const int split = lines.split_column;
  for (std::size_t k = 0; k < lines.y.size(); ++k) {
    if (std::abs(lines.y[k]) > 0.05) continue;  // rows beside the wound's widest part
    // Going outwards from the split (g′ = 1, 2, …) on either side, each line moves no more than the previous.
    for (int side : {-1, 1}) {
      double previous = 1e9;
      for (int g = 1; split + side * g >= 0 && split + side * g < static_cast<int>(lines.x.size()); ++g) {
        const int c = split + side * g;
        const double shift = std::abs(lines.X[c][k] - lines.x[c]);
        EXPECT_LE(shift, previous + 1e-12) << "row " << k << " g′ " << g;
        previous = shift;
      }
    }
    // Lines never cross or touch: spacing stays positive (at least 20 % of l by construction).
    for (std::size_t c = 0; c + 1 < lines.x.size(); ++c) {
      if (static_cast<int>(c) == split || static_cast<int>(c + 1) == split) continue;
      EXPECT_GT(lines.X[c + 1][k] - lines.X[c][k], 0.2 * lines.spacing) << "row " << k << " line " << c;
    }
  }
}

TEST(BarkFlow, LinesReturnToTheirOriginalSpacingAboveBelowAndBesideTheWound) {
  const HollowModel model = default_model();
  const BarkLines& lines = model.bark;
  double foot_top = -1e9, foot_bottom = 1e9;
  for (const auto& ring : model.callus.rings) foot_top = std::max(foot_top, ring.foot_xy.y), foot_bottom = std::min(foot_bottom, ring.foot_xy.y);
  for (std::size_t k = 0; k < lines.y.size(); ++k) {
    const bool clear_of_wound = lines.y[k] > foot_top || lines.y[k] < foot_bottom;
    for (std::size_t c = 0; c < lines.x.size(); ++c) {
      if (std::isnan(lines.X[c][k])) continue;
      if (clear_of_wound) EXPECT_DOUBLE_EQ(lines.X[c][k], lines.x[c]);
      // At the patch border the push has decayed to nothing.
      if (std::abs(lines.x[c]) >= model.patch_half_width - 1e-12) EXPECT_DOUBLE_EQ(lines.X[c][k], lines.x[c]);
    }
  }
  // Beside the wound, the spacing of neighbouring lines approaches l going outwards (the seed's relaxation):
  // compressed most next to the callus, within a few per cent at the patch border.
  const int split = lines.split_column;
  const int n = static_cast<int>(lines.x.size());
  for (std::size_t k = 0; k < lines.y.size(); ++k) {
    if (std::abs(lines.y[k]) > 0.05) continue;
    double previous_error = 1e9;
    for (int c = split + 1; c + 1 < n; ++c) {
      const double error = std::abs(lines.X[c + 1][k] - lines.X[c][k] - lines.spacing);
      EXPECT_LE(error, previous_error + 1e-12) << "row " << k << " pair " << c;
      previous_error = error;
    }
    EXPECT_LT(previous_error, 0.05 * lines.spacing);
    EXPECT_GT(std::abs(lines.X[split + 2][k] - lines.X[split + 1][k] - lines.spacing), 0.2 * lines.spacing);
  }
}

TEST(BarkFlow, DisplacementFieldMatchesItsFormula) {
  // A square foot |x| ≤ 0.02, |y| ≤ 0.05: reach 0.02 on both sides inside, patch P = 0.1 → k = min(2, 0.8·0.1/0.02) = 2.
  const WoundProfile square({{-0.02, -0.05}, {0.02, -0.05}, {0.02, 0.05}, {-0.02, 0.05}});
  const BarkFlow flow(square, 0.1);
  EXPECT_DOUBLE_EQ(flow.exponent(), 2.0);
  EXPECT_NEAR(flow.displaced(0.03, 0.0), 0.03 + 0.02 * 0.7 * 0.7, 1e-12);
  EXPECT_NEAR(flow.displaced(-0.05, 0.01), -0.05 - 0.02 * 0.5 * 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(flow.displaced(0.03, 0.06), 0.03);  // above the wound
  EXPECT_DOUBLE_EQ(flow.displaced(0.12, 0.0), 0.12);   // beyond the patch
}

TEST(BarkLift, BarkRisesNearTheWoundAndNotFarFromIt) {
  // Eq. 3.18 in metres: 1e-4 · (R_j / 2r) / d, capped at r / 2.
  EXPECT_NEAR(seed_bark_lift(0.02, 0.02, 0.05), 1e-4 * 0.5 / 0.05, 1e-15);
  EXPECT_DOUBLE_EQ(seed_bark_lift(0.03, 0.02, 1e-4), 0.01);
  const HollowMesh& mesh = default_model().mesh;
  double near_lift = 0, far_lift = 0;
  int near_n = 0, far_n = 0;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (mesh.part[v] != static_cast<int>(MeshPart::bark)) continue;
    const double height = mesh.vertices[v].z - 1.3;
    if (std::abs(height) < 0.05 && std::abs(mesh.bark_shift_m[v]) > 0.01) near_lift += mesh.bark_lift_m[v], ++near_n;
    if (std::abs(height) > 0.17) far_lift += mesh.bark_lift_m[v], ++far_n;
  }
  ASSERT_GT(near_n, 0);
  ASSERT_GT(far_n, 0);
  EXPECT_GT(near_lift / near_n, 5.0 * far_lift / far_n);
}

}  // namespace
}  // namespace heliostand::hollow
