#pragma once
// The balls that can shade a receiver, prepared once per solve. In periodic mode the stand is a torus:
// ball centres are wrapped into the plot, and (when asked) images of the balls near the plot edges are
// appended, shifted by one plot width/depth, so that a neighbourhood search sees across the edges.
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "light/leaf_ball.hpp"
#include "light/light_parameters.hpp"

#include <span>

namespace heliostand {

struct PlotTorus {
  bool periodic = false;
  glm::dvec2 origin{0.0};  // plot_x_min, plot_y_min
  glm::dvec2 size{0.0};    // width (x), depth (y), m

  static PlotTorus from(const LightParameters& parameters);
  glm::dvec3 wrap(glm::dvec3 point) const;  // into the plot (identity when not periodic)
};

struct OccluderSet {
  // Index k < ball_count is ball k of the stand itself; later entries are images (copies across the edges).
  std::vector<glm::dvec3> centres;
  std::vector<double> radii;
  std::vector<std::uint32_t> source;  // ball of the stand each entry is, or is an image of
  std::size_t ball_count = 0;
  double max_radius = 0;
};

// The stand's balls (wrapped into the plot when periodic). With `image_margin` > 0 and a periodic plot, images
// of every ball within `image_margin` of an edge are appended (all 8 neighbouring copies of the plot).
OccluderSet make_occluder_set(std::span<const LeafBall> balls, const PlotTorus& torus, double image_margin);

// Seed 000's shading test: does the half-line from `receiver` along unit `direction` intersect the ball?
// A receiver whose centre lies inside the ball is shaded in every direction.
inline bool ray_hits_ball(const glm::dvec3& receiver, const glm::dvec3& direction, const glm::dvec3& centre,
                          double radius) {
  const glm::dvec3 d = centre - receiver;
  const double r2 = radius * radius;
  if (d.x * d.x + d.y * d.y + d.z * d.z <= r2) return true;
  const double along = d.x * direction.x + d.y * direction.y + d.z * direction.z;
  if (along <= 0) return false;
  // squared distance from the ball centre to the ray: |d x N|^2 (no cancellation near tangency)
  const glm::dvec3 c{d.y * direction.z - d.z * direction.y, d.z * direction.x - d.x * direction.z,
                     d.x * direction.y - d.y * direction.x};
  return c.x * c.x + c.y * c.y + c.z * c.z <= r2;
}

}  // namespace heliostand
