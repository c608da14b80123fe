#include "compute/compute_backend.hpp"

#include <mutex>
#include <stdexcept>

#include <spdlog/spdlog.h>

#ifdef HELIOSTAND_HAVE_OPENCL
#include "compute/opencl_context.hpp"
#endif

namespace heliostand::compute {
namespace {

ComputeBackend reference_for_auto() {
  static std::once_flag warned;
  std::call_once(warned, [] {
    spdlog::warn(opencl_backend_built
                     ? "no OpenCL platform or device found; light and roots use the (slower) reference solvers"
                     : "this build of heliostand has no OpenCL backend; light and roots use the (slower) reference "
                       "solvers");
  });
  return ComputeBackend::reference();
}

}  // namespace

ComputeBackend ComputeBackend::reference() { return {}; }

ComputeBackend ComputeBackend::open(const DeviceChoice& choice) {
  if (choice.kind == DeviceChoice::Kind::reference) return reference();
#ifdef HELIOSTAND_HAVE_OPENCL
  if (auto device = open_opencl_device(choice.opencl_index)) {
    ComputeBackend backend;
    backend.opencl_ = std::make_shared<const OpenCLContext>(std::move(*device));
    return backend;
  }
  if (choice.kind == DeviceChoice::Kind::opencl)
    throw std::runtime_error("device '" + choice.text() +
                             "': no OpenCL device found (see `heliostand devices`); use --device reference");
#else
  if (choice.kind == DeviceChoice::Kind::opencl)
    throw std::runtime_error("device '" + choice.text() +
                             "': this build of heliostand has no OpenCL backend; use --device reference");
#endif
  return reference_for_auto();
}

std::optional<DeviceMemory> ComputeBackend::memory() const {
#ifdef HELIOSTAND_HAVE_OPENCL
  if (opencl_) return opencl_->memory;
#endif
  return std::nullopt;
}

std::string ComputeBackend::name() const {
#ifdef HELIOSTAND_HAVE_OPENCL
  if (opencl_) return "opencl:" + opencl_->description;
#endif
  return "reference";
}

}  // namespace heliostand::compute
