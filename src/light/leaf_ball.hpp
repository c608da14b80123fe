#pragma once
// A leaf ball (seed 000): the foliage of one living shoot as a sphere centred at the shoot's tip. It is all the
// light field needs to know of a tree, so the light solvers take leaf balls, never shoots or trees.
#include <glm/vec3.hpp>

namespace heliostand {

struct LeafBall {
  glm::dvec3 centre{0.0};   // m, stand coordinates (x east, y north, z up)
  double radius = 0;        // m
};

}  // namespace heliostand
