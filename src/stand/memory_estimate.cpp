#include "stand/memory_estimate.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <fstream>

#include "core/input_error.hpp"
#include "scenario/scenario.hpp"

namespace heliostand {
namespace {

constexpr double mib = 1024.0 * 1024.0;
constexpr double gib = 1024.0 * mib;
constexpr double fixed_bytes = 1.0 * gib;        // program, OpenCL runtime, far-field table (memory_estimate.hpp)
constexpr double bytes_per_tree = 1.75 * mib;    // docs/performance.md, the hectare for 60 years

// cgroup v2 (current systemd, Slurm with cgroup/v2, Docker): "max" or a number of bytes.
std::optional<std::uint64_t> cgroup_limit() {
  std::ifstream in("/sys/fs/cgroup/memory.max");
  std::string text;
  if (!(in >> text) || text == "max") return std::nullopt;
  try {
    return std::stoull(text);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// `ulimit -v` (batch schedulers such as PBS and Grid Engine set it for a job's memory).
std::optional<std::uint64_t> address_space_limit() {
  rlimit limit{};
  if (::getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return std::nullopt;
  return static_cast<std::uint64_t>(limit.rlim_cur);
}

std::optional<std::uint64_t> physical_memory() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page_size = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page_size <= 0) return std::nullopt;
  return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page_size);
}

}  // namespace

std::optional<std::uint64_t> usable_memory_bytes() {
  std::optional<std::uint64_t> usable;
  for (const auto& limit : {physical_memory(), cgroup_limit(), address_space_limit()}) {
    if (limit) usable = usable ? std::min(*usable, *limit) : *limit;
  }
  return usable;
}

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

}  // namespace heliostand
