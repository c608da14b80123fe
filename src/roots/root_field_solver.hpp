#pragma once
// The root-contact field (seed 003): for every growing root apex, what its root cap perceives inside
// its perception sphere —
//   contact avoidance  Vt = −Σ unit(direction from the apex to each other root segment in the sphere)
//   moisture pull      Vw =  Σ unit(probe_k) · moisture(apex + R · probe_k)   over the K probes
// computed for the roots of ALL trees at once. Two implementations (the OpenMM pattern, as for light):
// ReferenceRootFieldSolver, plain C++ and the oracle, and OpenCLRootFieldSolver (float on the device);
// make_root_field_solver() (roots/make_root_field_solver.hpp) picks the one of the run's compute backend.
// The probe directions are inputs, drawn on the host, so both backends see the same probes.
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "roots/soil_grid.hpp"

namespace heliostand::roots {

struct RootSegmentLine {
  glm::dvec3 start{0.0};
  glm::dvec3 end{0.0};
};

struct RootTipQuery {
  glm::dvec3 position{0.0};            // the apex (end of the segment it grows from)
  double perception_radius_m = 0.2;    // R
  int excluded[2] = {-1, -1};          // segment indices it does not feel: its own segment and its parent
};

struct RootFieldInput {
  std::span<const RootSegmentLine> segments;  // every living root segment of the stand
  std::span<const RootTipQuery> tips;
  std::span<const glm::dvec3> probes;         // probes_per_tip offsets per tip, in units of R (|p| <= 1)
  int probes_per_tip = 0;
  const SoilGrid* soil = nullptr;             // none: the moisture pull is zero
};

struct RootFieldSample {
  glm::dvec3 contact_avoidance{0.0};  // Vt before normalisation
  int contacts = 0;                   // segments felt (distance to their nearest point < R)
  glm::dvec3 moisture_pull{0.0};      // Vw before normalisation
};

// Segments nearer than this to the apex give no direction and are not counted (cl/roots.cl gets this value as
// the build option TOUCHING_DISTANCE).
inline constexpr double touching_distance_m = 1e-5;

class RootFieldSolver {
 public:
  virtual ~RootFieldSolver() = default;
  virtual std::string name() const = 0;  // "reference" or "opencl:<device>"
  // One sample per tip, in the order given.
  virtual std::vector<RootFieldSample> solve(const RootFieldInput& input) = 0;
};

}  // namespace heliostand::roots
