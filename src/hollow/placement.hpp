#pragma once
// Putting the plane outline onto the stem.
//
// Seed 004 (eqs. 3.7–3.8): a line L through the stem; A = the intersection on the wound's side, B = the
// midpoint of both intersections. The outline plane is rotated by a quaternion so that its normal lies on L,
// its origin moved to A, and every vertex V moved to where the segment B→V meets the surface.
// Our cylindrical placement instead reads the plane coordinates directly as stem-chart coordinates.
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "hollow/hollow_spec.hpp"
#include "hollow/stem_chart.hpp"

namespace heliostand::hollow {

// The seed's construction for a horizontal line L through the stem axis at the chart's centre.
struct TangentPlaneFrame {
  glm::dvec3 a_point;  // A: where L enters the stem on the wound's side
  glm::dvec3 b_point;  // B: midpoint of L's two intersections with the stem
  glm::dvec3 to_world(glm::dvec2 plane_xy) const;  // rotated, translated plane point (not yet projected)
  glm::dvec3 project(glm::dvec2 plane_xy, const TrunkSurface& trunk) const;  // onto the surface, from B
  glm::dvec3 x_axis, y_axis;  // images of the plane's e1, e2 after the quaternion rotation
};

TangentPlaneFrame tangent_plane_frame(const StemChart& chart);

// Outline vertices in stem-chart coordinates, for either placement.
std::vector<glm::dvec2> place_outline(const std::vector<glm::dvec2>& plane_loop, const StemChart& chart,
                                      Placement placement);

}  // namespace heliostand::hollow
