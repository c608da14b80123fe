#pragma once
// The light solver of a compute backend (compute/compute_backend.hpp): OpenCLLightSolver on the backend's
// OpenCL device, ReferenceLightSolver on the reference. Bad parameters throw std::invalid_argument.
#include <memory>

#include "compute/compute_backend.hpp"
#include "light/light_parameters.hpp"
#include "light/light_solver.hpp"

namespace heliostand {

std::unique_ptr<LightSolver> make_light_solver(const compute::ComputeBackend& backend,
                                               const LightParameters& parameters);

}  // namespace heliostand
