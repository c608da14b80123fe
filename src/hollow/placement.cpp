#include "hollow/placement.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

namespace heliostand::hollow {

glm::dvec3 TangentPlaneFrame::to_world(glm::dvec2 plane_xy) const {
  return a_point + plane_xy.x * x_axis + plane_xy.y * y_axis;
}

glm::dvec3 TangentPlaneFrame::project(glm::dvec2 plane_xy, const TrunkSurface& trunk) const {
  return trunk.cross_surface(b_point, to_world(plane_xy));
}

TangentPlaneFrame tangent_plane_frame(const StemChart& chart) {
  const TrunkSurface& trunk = chart.trunk();
  const double h0 = chart.centre_height();
  const double phi0 = chart.azimuth0();
  const glm::dvec3 facing{std::cos(phi0), std::sin(phi0), 0.0};
  const glm::dvec3 on_axis{0.0, 0.0, h0};
  // L: horizontal, through the axis, along the facing direction. Its two intersections with the stem:
  const double reach = 4.0 * trunk.radius(h0) + 1.0;
  const glm::dvec3 front = trunk.cross_surface(on_axis, on_axis + reach * facing);
  const glm::dvec3 back = trunk.cross_surface(on_axis, on_axis - reach * facing);

  TangentPlaneFrame frame;
  frame.a_point = front;
  frame.b_point = 0.5 * (front + back);
  // Eq. 3.7 embeds the plane with x′ across and y′ up (our z); its normal τ is then −e_y.
  const glm::dvec3 e1{1.0, 0.0, 0.0}, e2{0.0, 0.0, 1.0}, tau{0.0, -1.0, 0.0};
  // Eq. 3.8: quaternion about the axis perpendicular to a = B − A and τ, by the angle between them. We rotate
  // τ onto −a (the plane then faces out along L); the seed's axis a × τ with angle Θ turns the other way.
  const glm::dvec3 outward = glm::normalize(frame.a_point - frame.b_point);
  glm::dvec3 axis = glm::cross(tau, outward);
  const double theta = std::acos(std::clamp(glm::dot(tau, outward), -1.0, 1.0));
  axis = glm::length(axis) < 1e-12 ? glm::dvec3{0.0, 0.0, 1.0} : glm::normalize(axis);
  const glm::dquat q = glm::angleAxis(theta, axis);
  frame.x_axis = q * e1;
  frame.y_axis = q * e2;
  return frame;
}

std::vector<glm::dvec2> place_outline(const std::vector<glm::dvec2>& plane_loop, const StemChart& chart,
                                      Placement placement) {
  if (placement == Placement::cylindrical) return plane_loop;
  const TangentPlaneFrame frame = tangent_plane_frame(chart);
  std::vector<glm::dvec2> placed;
  placed.reserve(plane_loop.size());
  for (const glm::dvec2& v : plane_loop) placed.push_back(chart.chart_of(frame.project(v, chart.trunk())));
  return placed;
}

}  // namespace heliostand::hollow
