#pragma once
// The default light solver: cl/light.cl on an OpenCL device, float on the device, one work item per
// receiving ball. Same model and same inputs (near-field candidates, far-field table) as the reference.
#include <memory>

#include "light/light_parameters.hpp"
#include "light/light_solver.hpp"

namespace heliostand::compute {
struct OpenCLContext;
}

namespace heliostand {

class OpenCLLightSolver final : public LightSolver {
 public:
  // Runs on `device` (the run's compute backend, shared with the other solvers); builds cl/light.cl for it.
  OpenCLLightSolver(const LightParameters& parameters, const compute::OpenCLContext& device);
  ~OpenCLLightSolver() override;
  std::string name() const override;
  std::vector<LightSample> solve_for(std::span<const LeafBall> balls,
                                     std::span<const std::uint32_t> receivers) override;
  // Exact, open plots: every group in one launch (cl/light.cl light_each_alone); otherwise group by group.
  std::vector<LightSample> solve_each_alone(std::span<const LeafBall> balls,
                                            std::span<const std::size_t> group_start) override;

 private:
  struct Device;
  LightParameters parameters_;
  std::unique_ptr<Device> device_;
};

}  // namespace heliostand
