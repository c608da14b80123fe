#include "architecture/heliotropism.hpp"

#include <cmath>

#include <glm/geometric.hpp>

#include "geometry/vertical.hpp"

namespace heliostand {

glm::dvec3 heliotropic_direction(glm::dvec3 direction, glm::dvec3 light_vector, double strength) {
  const glm::dvec3 from = glm::normalize(direction);
  if (glm::length(light_vector) < 1e-12 || strength == 0.0) return from;
  const glm::dvec3 to = glm::normalize(light_vector);
  // Orthonormal pair (from, across) spanning the plane of E_s, E_e and the light vector.
  glm::dvec3 across = to - glm::dot(to, from) * from;
  if (glm::length(across) < 1e-12) {
    if (glm::dot(to, from) > 0.0) return from;  // already along the light
    across = vertical_up - glm::dot(vertical_up, from) * from;
    if (glm::length(across) < 1e-12) across = {1.0, 0.0, 0.0};
  }
  across = glm::normalize(across);
  const double angle = std::atan2(glm::dot(to, across), glm::dot(to, from));  // 0..pi
  const double turned = strength * angle;
  return std::cos(turned) * from + std::sin(turned) * across;
}

}  // namespace heliostand
