#include "roots/root_direction.hpp"

#include <cmath>

#include <glm/geometric.hpp>

#include "geometry/angles.hpp"

namespace heliostand::roots {

namespace {
// Any unit vector perpendicular to `v` (v unit).
glm::dvec3 perpendicular_to(const glm::dvec3& v) {
  const glm::dvec3 helper = std::abs(v.z) < 0.9 ? glm::dvec3(0.0, 0.0, 1.0) : glm::dvec3(1.0, 0.0, 0.0);
  return glm::normalize(glm::cross(v, helper));
}
}  // namespace

glm::dvec3 rotate_within_range(const glm::dvec3& parent, const AngleRangeDeg& range, RandomStream& random) {
  const glm::dvec3 axis = glm::normalize(parent);
  const double tilt = radians(random.uniform(range.min, range.max));
  const double azimuth = random.uniform(0.0, 2.0 * pi);
  const glm::dvec3 u = perpendicular_to(axis);
  const glm::dvec3 w = glm::cross(axis, u);
  const glm::dvec3 sideways = std::cos(azimuth) * u + std::sin(azimuth) * w;
  return glm::normalize(std::cos(tilt) * axis + std::sin(tilt) * sideways);
}

glm::dvec3 horizontal_of(const glm::dvec3& direction, const glm::dvec3& fallback) {
  const glm::dvec3 flat(direction.x, direction.y, 0.0);
  const double length = glm::length(flat);
  return length > 1e-9 ? flat / length : glm::normalize(glm::dvec3(fallback.x, fallback.y, 0.0));
}

glm::dvec3 unit_or_zero(const glm::dvec3& v, double negligible) {
  const double length = glm::length(v);
  return length > negligible ? v / length : glm::dvec3(0.0);
}

glm::dvec3 compose_direction(const TropismWeights& weights, const TropismVectors& vectors) {
  const glm::dvec3 v = weights.alpha * vectors.inherited + weights.beta * gravity_direction +
                       weights.gamma * vectors.diagravitropic + weights.delta * unit_or_zero(vectors.moisture_pull) +
                       weights.epsilon * unit_or_zero(vectors.contact_avoidance);
  const double length = glm::length(v);
  return length > 1e-12 ? v / length : vectors.inherited;
}

}  // namespace heliostand::roots
