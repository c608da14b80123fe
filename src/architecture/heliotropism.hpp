#pragma once
// Seed 000's heliotropism (Kanamaru et al. 1991, Fig. 4): a branch is rotated about its start E_s, in the plane
// that contains its end E_e and the light vector, toward the light vector by a fixed fraction I of the angle
// between them. I = 0: no heliotropism; I = 1: the branch points along the light vector.
#include <glm/vec3.hpp>

namespace heliostand {

// The new unit direction of a branch that points along `direction` (any length > 0). `light_vector` of
// length 0 (a balanced sky: no preferred direction) leaves the direction unchanged. A light vector exactly
// opposite the branch has no unique plane; the branch then turns in its own vertical plane (upward side
// first), which is where gravity-bound shoots turn.
glm::dvec3 heliotropic_direction(glm::dvec3 direction, glm::dvec3 light_vector, double strength);

}  // namespace heliostand
