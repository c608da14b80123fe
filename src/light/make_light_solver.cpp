#include "light/make_light_solver.hpp"

#include <mutex>
#include <stdexcept>

#include <spdlog/spdlog.h>

#include "compute/device_choice.hpp"
#include "light/reference_light_solver.hpp"
#ifdef HELIOSTAND_HAVE_OPENCL
#include "light/opencl_light_solver.hpp"
#endif

namespace heliostand {
namespace {

void warn_once_no_opencl() {
  static std::once_flag warned;
  std::call_once(warned, [] {
    spdlog::warn("no OpenCL platform or device found; the light field uses the (slower) reference solver");
  });
}

}  // namespace

std::unique_ptr<LightSolver> make_light_solver(const std::string& device, const LightParameters& parameters) {
  using Kind = compute::DeviceChoice::Kind;
  const auto choice = compute::DeviceChoice::parse(device);
  if (choice.kind == Kind::reference) return std::make_unique<ReferenceLightSolver>(parameters);
#ifdef HELIOSTAND_HAVE_OPENCL
  if (choice.kind == Kind::opencl || opencl_available())
    return std::make_unique<OpenCLLightSolver>(parameters, choice.opencl_index);
#else
  if (choice.kind == Kind::opencl)
    throw std::runtime_error("device '" + device + "': this build of heliostand has no OpenCL backend");
#endif
  warn_once_no_opencl();
  return std::make_unique<ReferenceLightSolver>(parameters);
}

}  // namespace heliostand
