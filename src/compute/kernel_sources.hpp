#pragma once
// OpenCL C sources from cl/, embedded into the binary at build time (cmake/EmbedKernels.cmake).
// For kernel work without rebuilding, HELIOSTAND_KERNEL_DIR may name a folder whose files
// take precedence over the embedded copies.
#include <string>
#include <string_view>
#include <vector>

namespace heliostand::compute {

struct EmbeddedKernel {
  std::string_view name;  // file name in cl/, e.g. "light.cl"
  std::string_view source;
};

// All files of cl/ as they were at build time (generated translation unit).
const std::vector<EmbeddedKernel>& embedded_kernels();

// The source of one kernel file, with every `#include "x.clh"` line replaced by that file's text,
// so the OpenCL compiler needs no include path. Throws std::runtime_error if the file is unknown.
std::string kernel_source(std::string_view file_name);

}  // namespace heliostand::compute
