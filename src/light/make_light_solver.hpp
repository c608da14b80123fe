#pragma once
// Picks the light solver for a --device string: "auto" (default), "reference", "opencl", "opencl:N".
// auto without any OpenCL platform warns once (spdlog) and falls back to the reference solver; an explicit
// opencl device that does not exist is an error (std::runtime_error). A malformed string throws
// std::invalid_argument.
#include <memory>
#include <string>

#include "light/light_parameters.hpp"
#include "light/light_solver.hpp"

namespace heliostand {

std::unique_ptr<LightSolver> make_light_solver(const std::string& device, const LightParameters& parameters);

}  // namespace heliostand
