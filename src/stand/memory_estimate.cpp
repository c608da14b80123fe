#include "stand/memory_estimate.hpp"

#include <fmt/format.h>

#include "core/input_error.hpp"
#include "core/usable_memory.hpp"
#include "scenario/scenario.hpp"

namespace heliostand {
namespace {

constexpr double mib = bytes_per_gib / 1024.0;
constexpr double fixed_bytes = 1.0 * bytes_per_gib;  // program, OpenCL runtime, far-field table (memory_estimate.hpp)
constexpr double bytes_per_tree = 1.75 * mib;        // docs/performance.md, the hectare for 60 years
constexpr double default_table_mb = LightParameters{}.far_field_table_mb;  // inside fixed_bytes
constexpr double table_layouts = 2;                  // the OpenCL solver keeps two layouts of the table

// The far-field table's share beyond the fixed part: twice what its cap allows above the default (none for the
// exact light, which has no far field).
double far_field_table_bytes(const LightParameters& light) {
  if (light.exact || light.far_field_table_mb <= default_table_mb) return 0;
  return table_layouts * (light.far_field_table_mb - default_table_mb) * 1e6;
}

// The formula in words, from the constants above, for the refusals: "1 GiB + 1.75 MiB per tree[ + twice ...]".
std::string formula(bool with_table) {
  return fmt::format("{:g} GiB + {:g} MiB per tree{}", fixed_bytes / bytes_per_gib, bytes_per_tree / mib,
                     with_table ? fmt::format(" + twice the far-field table's cap above {:g} MB", default_table_mb)
                                : "");
}

}  // namespace

MemoryEstimate estimate_run_memory(const Scenario& scenario) {
  const std::size_t trees = scenario.survey.trees.size();
  const double table = far_field_table_bytes(scenario.light);
  return {static_cast<std::uint64_t>(fixed_bytes + bytes_per_tree * static_cast<double>(trees) + table), trees,
          static_cast<std::uint64_t>(table)};
}

void refuse_beyond_memory(const Scenario& scenario, const MemoryEstimate& estimate, std::uint64_t usable) {
  if (estimate.bytes <= usable) return;
  const std::string file = scenario.file.string();
  if (estimate.far_field_table_bytes > 0 && estimate.bytes - estimate.far_field_table_bytes <= usable)
    throw InputError({{file, 0, "light.far_field_table_mb",
                       fmt::format("a far-field table of up to {} MB brings the run to about {} ({}, "
                                   "docs/performance.md \"Memory\"), more than the {} this machine lets the run use: "
                                   "lower it (the far field's cells grow coarser instead)",
                                   scenario.light.far_field_table_mb, gibibytes(estimate.bytes), formula(true),
                                   gibibytes(usable))}},
                     "key");
  throw InputError({{file, 0, "stand.survey",
                     fmt::format("{} trees need about {} ({}, docs/performance.md \"Memory\"), more than the {} "
                                 "this machine lets the run use: grow the stand in parts, or on a larger machine",
                                 estimate.trees, gibibytes(estimate.bytes),
                                 formula(estimate.far_field_table_bytes > 0), gibibytes(usable))}},
                   "key");
}

void refuse_run_beyond_this_machine(const Scenario& scenario) {
  if (const auto usable = usable_memory_bytes()) refuse_beyond_memory(scenario, estimate_run_memory(scenario), *usable);
}

}  // namespace heliostand
