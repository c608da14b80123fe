#pragma once
// The root-contact field solver of a compute backend (compute/compute_backend.hpp): OpenCLRootFieldSolver on the
// backend's OpenCL device (the device the light field runs on), ReferenceRootFieldSolver on the reference.
#include <memory>

#include "compute/compute_backend.hpp"
#include "roots/root_field_solver.hpp"

namespace heliostand::roots {

std::unique_ptr<RootFieldSolver> make_root_field_solver(const compute::ComputeBackend& backend);

}  // namespace heliostand::roots
