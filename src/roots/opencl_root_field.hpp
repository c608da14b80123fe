#pragma once
// The root-contact field on OpenCL (kernel cl/roots.cl, float on the device). The host builds the
// uniform segment grid (segment_grid.hpp), converts positions to floats relative to one frame origin,
// and reads back one contact vector and one moisture pull per apex. Until the shared OpenCL context of
// src/compute/ exists, this class owns its own context, queue and program (the lead moves it over).
#include <memory>

#include "roots/root_field_solver.hpp"

namespace heliostand::roots {

class OpenCLRootFieldSolver final : public RootFieldSolver {
 public:
  // The device_index-th device over all platforms (0 = the first, PoCL on a CPU-only machine).
  // Throws std::runtime_error if there is no OpenCL platform or no such device.
  explicit OpenCLRootFieldSolver(int device_index = 0);
  ~OpenCLRootFieldSolver() override;
  std::string name() const override;
  std::vector<RootFieldSample> solve(const RootFieldInput& input) override;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace heliostand::roots
