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

struct TileCandidates;

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
  // One pass (cl/light.cl light_culled_and_alone) when the device is a CPU (on a GPU two passes are quicker), this
  // solver is culled, `alone` is an exact open-plot OpenCLLightSolver on the same device with the same sky patches
  // and transmittance, and, on a periodic plot, no group is so wide that the image of one of its balls comes within
  // the cut-off of another; std::nullopt otherwise.
  // The alone samples are solve_each_alone's bit for bit; the stand's are solve's up to float round-off (each
  // tree's own balls are offset in the tree's own frame, docs/light.md "The stand and each tree alone in one pass").
  std::optional<StandAndAlone> solve_with_each_alone(std::span<const LeafBall> balls,
                                                     std::span<const std::size_t> group_start,
                                                     const LightSolver& alone) override;

 private:
  struct Device;
  struct AloneLight;
  // One solve's parts on the device, in the order the solve makes them (opencl_light_solver.cpp).
  struct DeviceStand;
  struct FarFieldTable;
  struct FusedPass;
  struct TileScan;
  struct CulledLight;
  // solve_for; with `alone` (a culled solver only), also each receiver's group alone, into alone->samples.
  std::vector<LightSample> solve_receivers(std::span<const LeafBall> balls, std::span<const std::uint32_t> receivers,
                                           AloneLight* alone);
  DeviceStand stand_on_device(std::span<const LeafBall> balls) const;
  std::vector<LightSample> solve_exact(const DeviceStand& stand, std::span<const std::uint32_t> receivers);
  std::vector<LightSample> solve_culled(const DeviceStand& stand, std::span<const LeafBall> balls,
                                        std::span<const std::uint32_t> receivers, AloneLight* alone);
  FarFieldTable far_field_on_device(const DeviceStand& stand, std::span<const std::uint32_t> receivers);
  FusedPass fused_pass_on_device(const DeviceStand& stand, std::span<const LeafBall> balls,
                                 const AloneLight& alone) const;
  TileScan tile_scan_on_device(const DeviceStand& stand, const TileCandidates& near,
                               std::span<const std::uint32_t> receivers, const FusedPass* fused);
  CulledLight shade_culled(const DeviceStand& stand, const FarFieldTable& far, const TileScan& scan,
                           const FusedPass* fused);
  bool groups_clear_of_own_images(std::span<const LeafBall> balls, std::span<const std::size_t> group_start) const;
  LightParameters parameters_;
  std::unique_ptr<Device> device_;
};

}  // namespace heliostand
