#pragma once
#include <CLI/CLI.hpp>

namespace heliostand::cli {

// `heliostand bench stand SCENARIO`: a grown scenario's cost; `heliostand bench light [--balls N ...] [--stand SCENARIO ...]`:
// light solver timings and errors on synthetic canopies and on established stands. Both print JSON.
void add_bench_command(CLI::App& app);

}  // namespace heliostand::cli
