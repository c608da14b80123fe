#pragma once
// The wound outline of seed 004 (eqs. 3.2–3.6): two quintic Bézier curves joined end to end into a ring,
// built in a plane (x′ across, y′ up) from the wound's width W and height H, then sampled so that
// consecutive vertices are a fixed arc length apart.
#include <array>
#include <vector>

#include <glm/vec2.hpp>

namespace heliostand::hollow {

using ControlPoints = std::array<glm::dvec2, 6>;

// Eq. 3.4: P0 = (0, −H/2), P1 = (W/4, −H/2), P2 = (W/2, −H/4), P3 = (W/2, 0), P4 = (W/4, H/2), P5 = (0, H/2).
// P1 and P4 share y′ with P0 and P5 so that the two curves meet with a common (horizontal) tangent.
ControlPoints right_control_points(double width, double height);
// Eq. 3.5: the same points mirrored in x′.
ControlPoints left_control_points(double width, double height);

glm::dvec2 bezier5(const ControlPoints& p, double t);             // eq. 3.2 with Bernstein basis 3.3
glm::dvec2 bezier5_derivative(const ControlPoints& p, double t);  // K′(t) = 5 Σ B⁴_i(t)(P_{i+1} − P_i)

// Parameters t_0 = 0, t_{k+1} = t_k + u(t_k) with u(t) = step / |K′(t)| (eq. 3.6: step = 0.1 seed units),
// ending with t = 1. A last step shorter than half a step is merged into the end point.
std::vector<double> arc_length_parameters(const ControlPoints& p, double step);

// The closed outline V_1..V_γ: from the bottom apex up the right curve, then down the left curve
// (counter-clockwise, x′ right, y′ up). The first vertex is the bottom apex; the loop is not repeated.
std::vector<glm::dvec2> sample_outline(double width, double height, double step);

// Index of the vertex with the largest / smallest y′ (the seed's split vertex V′_j is the top one).
int top_vertex(const std::vector<glm::dvec2>& loop);
int bottom_vertex(const std::vector<glm::dvec2>& loop);

// Outward unit normals of a counter-clockwise loop (central differences): the right of the direction of
// travel. With period > 0, x is periodic (a rim running once around the stem in the stem chart).
std::vector<glm::dvec2> outward_normals(const std::vector<glm::dvec2>& loop, double period = 0.0);

}  // namespace heliostand::hollow
