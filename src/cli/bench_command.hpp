#pragma once
#include <CLI/CLI.hpp>

namespace heliostand::cli {

// `heliostand bench light [--balls N ...]`: solver timings and errors on synthetic canopies, as JSON.
void add_bench_command(CLI::App& app);

}  // namespace heliostand::cli
