#pragma once
// The compute backend of a run, chosen once from --device / run.device (OpenMM's Platform): every solver
// factory takes it, so the light field and the root-contact field run on the same device, and on OpenCL they
// share its one context and in-order queue.
//   reference  the plain C++ solvers, the oracles
//   OpenCL     one device, opened once: context, queue and device (compute/opencl_context.hpp)
// This header needs no OpenCL headers, so code built without the OpenCL backend holds a backend too.
#include <memory>
#include <optional>
#include <string>

#include "compute/device_choice.hpp"
#include "compute/device_memory.hpp"

namespace heliostand::compute {

struct OpenCLContext;  // compute/opencl_context.hpp, in OpenCL builds only

class ComputeBackend {
 public:
  static ComputeBackend reference();
  // auto: the default OpenCL device; with none (or in a build without OpenCL) a one-time warning and the
  // reference. opencl / opencl:N: that device; std::runtime_error when it does not exist.
  static ComputeBackend open(const DeviceChoice& choice);

  bool is_opencl() const { return opencl_ != nullptr; }
  // The device every OpenCL solver of this backend runs on; null for the reference.
  const OpenCLContext* opencl() const { return opencl_.get(); }
  // What the device holds (compute/device_memory.hpp); std::nullopt for the reference, whose memory is the host's.
  std::optional<DeviceMemory> memory() const;
  std::string name() const;  // "reference" or "opencl:<platform> / <device>" (logs, run.json, solver names)

 private:
  std::shared_ptr<const OpenCLContext> opencl_;
};

}  // namespace heliostand::compute
