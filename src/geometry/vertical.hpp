#pragma once
// The stand's frame is x east, y north, z up; gravity and the stems' axes run along z.
#include <glm/vec3.hpp>

namespace heliostand {

inline const glm::dvec3 vertical_up{0.0, 0.0, 1.0};

}  // namespace heliostand
