#pragma once
// The light field of seed 000 (Kanamaru et al.): for every leaf ball, the sky light that reaches it
// through all other leaf balls of the stand, and the direction it comes from. Two implementations
// (the OpenMM pattern): ReferenceLightSolver, the plain C++ oracle, and OpenCLLightSolver, the default.
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "architecture/shoot.hpp"

namespace heliostand {

struct LightSample {
  double light = 1.0;                 // Σ B S / Σ B0 S, in 0..1
  glm::dvec3 vector{0.0, 0.0, 1.0};   // normalize(Σ N B S)
};

class LightSolver {
 public:
  virtual ~LightSolver() = default;
  virtual std::string name() const = 0;  // "reference" or "opencl:<device>"
  // One sample per ball, in the order given.
  virtual std::vector<LightSample> solve(std::span<const LeafBall> balls) = 0;
};

}  // namespace heliostand
