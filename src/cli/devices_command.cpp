#include "cli/devices_command.hpp"

#include <iostream>

#include <fmt/format.h>

#include "compute/device_choice.hpp"
#include "compute/device_memory.hpp"

namespace heliostand::cli {

void add_devices_command(CLI::App& app) {
  auto* devices = app.add_subcommand("devices", "List the compute devices (--device values) and mark the default");
  devices->callback([] {
    const auto list = compute::list_opencl_devices();
    if (!compute::opencl_backend_built)
      std::cout << "this build has no OpenCL backend (HELIOSTAND_OPENCL=OFF): --device auto uses the reference solvers\n";
    else if (list.empty())
      std::cout << "no OpenCL platform or device found: --device auto uses the reference solvers\n";
    for (const auto& d : list)
      std::cout << fmt::format("{} opencl:{}  {} / {}  ({}, {}, {} compute units, {:.0f} MB memory, {:.0f} MB a "
                               "buffer){}\n",
                               d.is_default ? "*" : " ", d.index, d.platform, d.name, d.type, d.version,
                               d.compute_units, compute::whole_megabytes(d.memory.total_bytes),
                               compute::whole_megabytes(d.memory.buffer_bytes), d.is_default ? "  [default]" : "");
    std::cout << fmt::format("{} reference  plain C++ solvers of light and roots (the oracles; always available){}\n",
                             list.empty() ? "*" : " ", list.empty() ? "  [default]" : "");
  });
}

}  // namespace heliostand::cli
