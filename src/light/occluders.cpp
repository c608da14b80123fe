#include "light/occluders.hpp"

#include <algorithm>
#include <cmath>

#include <glm/vec2.hpp>

namespace heliostand {

PlotTorus PlotTorus::from(const LightParameters& p) {
  PlotTorus torus;
  torus.periodic = p.periodic;
  torus.origin = {p.plot_x_min, p.plot_y_min};
  torus.size = {p.plot_x_max - p.plot_x_min, p.plot_y_max - p.plot_y_min};
  return torus;
}

glm::dvec3 PlotTorus::wrap(glm::dvec3 point) const {
  if (!periodic) return point;
  for (int axis = 0; axis < 2; ++axis) {
    double offset = std::fmod(point[axis] - origin[axis], size[axis]);
    if (offset < 0) offset += size[axis];
    point[axis] = origin[axis] + offset;
  }
  return point;
}

OccluderSet make_occluder_set(std::span<const LeafBall> balls, const PlotTorus& torus, double image_margin) {
  OccluderSet set;
  set.ball_count = balls.size();
  for (std::size_t k = 0; k < balls.size(); ++k) {
    set.centres.push_back(torus.wrap(balls[k].centre));
    set.radii.push_back(balls[k].radius);
    set.source.push_back(static_cast<std::uint32_t>(k));
    set.max_radius = std::max(set.max_radius, balls[k].radius);
  }
  if (!torus.periodic || image_margin <= 0) return set;
  for (std::size_t k = 0; k < balls.size(); ++k) {
    const glm::dvec3 c = set.centres[k];
    for (int sx = -1; sx <= 1; ++sx)
      for (int sy = -1; sy <= 1; ++sy) {
        if (sx == 0 && sy == 0) continue;
        const glm::dvec3 image = c + glm::dvec3(sx * torus.size.x, sy * torus.size.y, 0.0);
        // keep the image only if it lies within the margin of the plot
        const double gap_x = std::max({torus.origin.x - image.x, image.x - (torus.origin.x + torus.size.x), 0.0});
        const double gap_y = std::max({torus.origin.y - image.y, image.y - (torus.origin.y + torus.size.y), 0.0});
        if (gap_x > image_margin || gap_y > image_margin) continue;
        set.centres.push_back(image);
        set.radii.push_back(balls[k].radius);
        set.source.push_back(static_cast<std::uint32_t>(k));
      }
  }
  return set;
}

}  // namespace heliostand
