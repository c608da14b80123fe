#pragma once
// The default light solver: cl/light.cl on an OpenCL device, float on the device, one work item per
// receiving ball. Same model and same inputs (near-field candidates, far-field table) as the reference.
#include <memory>
#include <optional>

#include "light/light_parameters.hpp"
#include "light/light_solver.hpp"

namespace heliostand {

class OpenCLLightSolver final : public LightSolver {
 public:
  // Device `index` (nullopt = default). Throws std::runtime_error when there is no such OpenCL device.
  OpenCLLightSolver(const LightParameters& parameters, std::optional<int> device_index);
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

// True when at least one OpenCL device exists (used by the factory and by tests to skip OpenCL cases).
bool opencl_available();

}  // namespace heliostand
