#pragma once
// `heliostand bench stand SCENARIO`: grows a scenario as `heliostand grow --no-vtk` does (the tables are written,
// the VTK series is not) and reports what the run cost as JSON: seconds per stage of the simulated year (the
// clock of run.json), total seconds, tree-years per second, what the living trees hold at the end (leaf balls,
// shoots, root segments), the heap in use after the last year (what the stand costs to hold) and the process's
// peak resident memory. docs/performance.md "Whole stand".
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace heliostand {

struct StandBenchmarkOptions {
  std::filesystem::path scenario;
  std::optional<int> years;             // overrides run.years
  std::optional<std::uint64_t> seed;    // overrides run.seed
  std::string device;                   // overrides run.device when not empty
  // Where the tables go: empty = a fresh temporary folder, removed afterwards; else kept there (--force rules).
  std::filesystem::path tables_folder;
  bool force = false;
  std::string command_line;             // recorded in the tables' run.json
};

// Runs the stand and returns the JSON report; the run's log goes to spdlog (stderr).
std::string run_stand_benchmark(const StandBenchmarkOptions& options);

// The process's peak resident set so far (getrusage ru_maxrss), bytes.
std::size_t peak_resident_bytes();

}  // namespace heliostand
