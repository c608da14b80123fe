#include "stand/memory_estimate.hpp"

#include <fmt/format.h>

#include "core/input_error.hpp"
#include "core/usable_memory.hpp"
#include "scenario/scenario.hpp"

namespace heliostand {
namespace {

constexpr double mib = 1024.0 * 1024.0;
constexpr double gib = 1024.0 * mib;
constexpr double fixed_bytes = 1.0 * gib;        // program, OpenCL runtime, far-field table (memory_estimate.hpp)
constexpr double bytes_per_tree = 1.75 * mib;    // docs/performance.md, the hectare for 60 years

}  // namespace

MemoryEstimate estimate_run_memory(const Scenario& scenario) {
  const std::size_t trees = scenario.survey.trees.size();
  return {static_cast<std::uint64_t>(fixed_bytes + bytes_per_tree * static_cast<double>(trees)), trees};
}

void refuse_beyond_memory(const Scenario& scenario, const MemoryEstimate& estimate, std::uint64_t usable) {
  if (estimate.bytes <= usable) return;
  throw InputError({{scenario.file.string(), 0, "stand.survey",
                     fmt::format("{} trees need about {:.1f} GiB (1 GiB + 1.75 MiB per tree, docs/performance.md "
                                 "\"Memory\"), more than the {:.1f} GiB this machine lets the run use: grow the "
                                 "stand in parts, or on a larger machine",
                                 estimate.trees, static_cast<double>(estimate.bytes) / gib,
                                 static_cast<double>(usable) / gib)}},
                   "key");
}

void refuse_run_beyond_this_machine(const Scenario& scenario) {
  if (const auto usable = usable_memory_bytes()) refuse_beyond_memory(scenario, estimate_run_memory(scenario), *usable);
}

}  // namespace heliostand
