// Seed 004 eqs. 3.2–3.6: the two-Bézier wound outline and its arc-length sampling.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "hollow/wound_outline.hpp"

namespace heliostand::hollow {
namespace {

TEST(WoundOutline, ControlPointsFollowEquation34AndMirrorForEquation35) {
  const ControlPoints p = right_control_points(8.0, 4.0);
  EXPECT_EQ(p[0], glm::dvec2(0, -2));
  EXPECT_EQ(p[1], glm::dvec2(2, -2));   // W/4, −H/2
  EXPECT_EQ(p[2], glm::dvec2(4, -1));   // W/2, (2−1)H/4 − H/2
  EXPECT_EQ(p[3], glm::dvec2(4, 0));    // W/2, (3−1)H/4 − H/2
  EXPECT_EQ(p[4], glm::dvec2(2, 2));
  EXPECT_EQ(p[5], glm::dvec2(0, 2));
  const ControlPoints q = left_control_points(8.0, 4.0);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(q[i], glm::dvec2(-p[i].x, p[i].y));
}

TEST(WoundOutline, BezierMatchesHandComputedBernsteinSums) {
  const ControlPoints p = right_control_points(8.0, 4.0);
  // t = 1/2: all Bernstein weights are C(5,i)/32 → x = (5·2 + 10·4 + 10·4 + 5·2)/32 = 3.125,
  // y = (−2 − 10 − 10 + 0 + 10 + 2)/32 = −0.3125.
  const glm::dvec2 mid = bezier5(p, 0.5);
  EXPECT_NEAR(mid.x, 3.125, 1e-12);
  EXPECT_NEAR(mid.y, -0.3125, 1e-12);
  EXPECT_EQ(bezier5(p, 0.0), p[0]);
  EXPECT_EQ(bezier5(p, 1.0), p[5]);
  // K′(0) = 5 (P1 − P0) = (10, 0): horizontal, so the mirrored curve joins smoothly.
  const glm::dvec2 start = bezier5_derivative(p, 0.0);
  EXPECT_NEAR(start.x, 10.0, 1e-12);
  EXPECT_NEAR(start.y, 0.0, 1e-12);
  // Derivative against a central difference at t = 0.3.
  const glm::dvec2 numeric = (bezier5(p, 0.3 + 1e-6) - bezier5(p, 0.3 - 1e-6)) / 2e-6;
  EXPECT_NEAR(glm::length(numeric - bezier5_derivative(p, 0.3)), 0.0, 1e-6);
}

TEST(WoundOutline, SamplesAreOneStepOfArcApart) {
  const double step = 0.001;  // the seed's 0.1 units at 1 unit = 1 cm
  const auto loop = sample_outline(0.12, 0.20, step);
  double shortest = 1e9, longest = 0.0, perimeter = 0.0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const double d = glm::length(loop[(i + 1) % loop.size()] - loop[i]);
    shortest = std::min(shortest, d), longest = std::max(longest, d);
    perimeter += d;
  }
  EXPECT_GT(shortest, 0.5 * step);
  EXPECT_LT(longest, 1.5 * step);  // a last step shorter than half a step is merged into the apex
  EXPECT_NEAR(static_cast<double>(loop.size()), perimeter / step, 3.0);
  // All but the steps at the two apexes are within 3 % of the step (first-order steps u = step/|K′|).
  int off = 0;
  for (std::size_t i = 0; i < loop.size(); ++i)
    off += std::abs(glm::length(loop[(i + 1) % loop.size()] - loop[i]) - step) > 0.03 * step;
  EXPECT_LE(off, 4);
}

TEST(WoundOutline, LoopStartsAtTheBottomApexRunsCounterClockwiseAndIsMirrorSymmetric) {
  const auto loop = sample_outline(0.10, 0.16, 0.001);
  EXPECT_EQ(loop.front(), glm::dvec2(0.0, -0.08));
  EXPECT_EQ(bottom_vertex(loop), 0);
  EXPECT_NEAR(loop[top_vertex(loop)].y, 0.08, 1e-12);
  double twice_area = 0.0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const auto& a = loop[i];
    const auto& b = loop[(i + 1) % loop.size()];
    twice_area += a.x * b.y - a.y * b.x;
  }
  EXPECT_GT(twice_area, 0.0);
  // Going up the right side and down the left visits mirror images.
  const int n = static_cast<int>(loop.size());
  for (int i = 1; i < n / 2; i += 17) {
    EXPECT_NEAR(loop[i].x, -loop[n - i].x, 1e-12);
    EXPECT_NEAR(loop[i].y, loop[n - i].y, 1e-12);
  }
  // Widest point at K(1/2): 0.390625 W.
  double widest = 0.0;
  for (const auto& v : loop) widest = std::max(widest, v.x);
  EXPECT_NEAR(widest, 0.390625 * 0.10, 2e-5);
}

TEST(WoundOutline, OutwardNormalsPointAwayFromTheCentre) {
  const auto loop = sample_outline(0.10, 0.16, 0.001);
  const auto normals = outward_normals(loop);
  for (std::size_t i = 0; i < loop.size(); i += 11) EXPECT_GT(glm::dot(normals[i], loop[i]), 0.0) << i;
}

}  // namespace
}  // namespace heliostand::hollow
