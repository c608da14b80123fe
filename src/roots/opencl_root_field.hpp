#pragma once
// The root-contact field on OpenCL (kernel cl/roots.cl, float on the device). Once a year (begin_year) the host
// builds the uniform segment grid (segment_grid.hpp) and writes the segments, as floats relative to one frame
// origin, and the soil's moisture into device buffers kept from one year to the next; each query then writes only
// its apices and probes and reads back one contact vector and one moisture pull per apex. It runs on the compute backend's device
// (compute/compute_backend.hpp), in the context and queue the light solver uses too.
#include <memory>

#include "roots/root_field_solver.hpp"

namespace heliostand::compute {
struct OpenCLContext;
}

namespace heliostand::roots {

class OpenCLRootFieldSolver final : public RootFieldSolver {
 public:
  // Builds cl/roots.cl for `device`; throws std::runtime_error with the build log if it does not build.
  explicit OpenCLRootFieldSolver(const compute::OpenCLContext& device);
  ~OpenCLRootFieldSolver() override;
  std::string name() const override;
  void begin_year(const RootFieldYear& year) override;
  std::vector<RootFieldSample> query(std::span<const RootTipQuery> tips, std::span<const glm::dvec3> probes,
                                     int probes_per_tip) override;
  void end_year() override;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace heliostand::roots
