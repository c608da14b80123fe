#include "stand/memory_estimate.hpp"

#include <fmt/format.h>

#include "core/input_error.hpp"
#include "core/usable_memory.hpp"
#include "light/far_field_buffers.hpp"
#include "scenario/scenario.hpp"

namespace heliostand {
namespace {

constexpr double mib = bytes_per_gib / 1024.0;
constexpr double fixed_bytes = 1.0 * bytes_per_gib;  // program, OpenCL runtime, far-field table (memory_estimate.hpp)
constexpr double bytes_per_tree = 1.75 * mib;        // docs/performance.md, the hectare for 60 years

// The formula in words, from the constants above, for the refusals: "1 GiB + 1.75 MiB per tree[ + twice ...]".
std::string formula(bool with_table) {
  return fmt::format("{:g} GiB + {:g} MiB per tree{}", fixed_bytes / bytes_per_gib, bytes_per_tree / mib,
                     with_table ? " + " + far_field_table_memory_term() : "");
}

}  // namespace

MemoryEstimate estimate_run_memory(const Scenario& scenario) {
  const std::size_t trees = scenario.survey.trees.size();
  const double table = far_field_table_bytes_beyond_default(scenario.light);
  return {static_cast<std::uint64_t>(fixed_bytes + bytes_per_tree * static_cast<double>(trees) + table), trees,
          static_cast<std::uint64_t>(table)};
}

std::optional<std::string> far_field_table_beyond_memory(const Scenario& scenario, const MemoryEstimate& estimate,
                                                         std::uint64_t usable) {
  if (estimate.bytes <= usable || estimate.far_field_table_bytes == 0) return std::nullopt;
  if (estimate.bytes - estimate.far_field_table_bytes > usable) return std::nullopt;  // the stand alone is too large
  return fmt::format("a far-field table of up to {} MB brings the run to about {} ({}, docs/performance.md "
                     "\"Memory\"), more than the {} this machine lets the run use: lower it (the far field's cells "
                     "grow coarser instead)",
                     scenario.light.far_field_table_mb, gibibytes(estimate.bytes), formula(true), gibibytes(usable));
}

void refuse_beyond_memory(const Scenario& scenario, const MemoryEstimate& estimate, std::uint64_t usable) {
  if (estimate.bytes <= usable) return;
  const std::string file = scenario.file.string();
  if (auto reason = far_field_table_beyond_memory(scenario, estimate, usable))
    throw InputError({{file, 0, "light.far_field_table_mb", *reason}}, "key");
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
