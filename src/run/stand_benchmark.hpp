#pragma once
// `heliostand bench stand SCENARIO`: grows a scenario as `heliostand grow --no-vtk` does (the tables are written,
// the VTK series is not) and reports what the run cost as JSON: seconds per stage of the simulated year (the
// clock of run.json), total seconds, tree-years per second, what the living trees hold at the end (leaf balls,
// shoots, root segments), the heap in use after the last year (what the stand costs to hold) and the process's
// peak resident memory. Its fields: validation/bench/README.md; its uses: docs/performance.md "Measuring again".
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "scenario/scenario.hpp"

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

// The scenario of `options` read and checked, its --years and --seed applied, its warnings logged and a stand beyond
// the machine's memory refused: everything that can be wrong with the input, found before anything is grown or written.
Scenario stand_benchmark_scenario(const StandBenchmarkOptions& options);

// Grows `scenario` (from stand_benchmark_scenario) and returns the JSON report; the run's log goes to spdlog (stderr).
std::string run_stand_benchmark(const Scenario& scenario, const StandBenchmarkOptions& options);

// The process's peak resident set so far (getrusage ru_maxrss), bytes.
std::size_t peak_resident_bytes();

// The operating system's part in the process so far, by its own account (getrusage, RUSAGE_SELF): its CPU seconds in
// the system (every thread's) and the pages it touched for the first time (minor faults, each a page the system had to
// find and clear: what a first solve's fresh tables cost, docs/performance.md "What a first touch costs here, measured
// apart"). The kernel splits the process's CPU time between user and system by where its clock ticks found it, so a
// run of under a second with a few tens of ms in the system may be told 0 s of it.
struct SystemPart {
  double cpu_seconds = 0;
  long minor_page_faults = 0;
};

// std::nullopt where the account cannot be read.
std::optional<SystemPart> system_part_so_far();

}  // namespace heliostand
