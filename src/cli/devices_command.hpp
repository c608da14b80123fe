#pragma once
#include <CLI/CLI.hpp>

namespace heliostand::cli {

// `heliostand devices`: the compute backends available here (OpenCL platforms/devices, default marked).
void add_devices_command(CLI::App& app);

}  // namespace heliostand::cli
