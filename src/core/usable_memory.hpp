#pragma once
// The memory this process may use. Work far beyond it is refused before it starts, with the figures, instead of
// dying of the OOM killer hours later or taking the machine down with it: a stand's run (stand/memory_estimate.hpp,
// for `grow`, `bench stand` and `bench light --stand`) and a synthetic canopy of `bench light --balls`
// (light/light_benchmark.hpp).
#include <cstdint>
#include <optional>
#include <string>

namespace heliostand {

// The least of the machine's physical memory, its cgroup limit (a Slurm job, a container) and its address-space
// limit (`ulimit -v`). Nothing when none can be read.
std::optional<std::uint64_t> usable_memory_bytes();

// Bytes in a gibibyte, for the estimates' figures and their formulas in words.
inline constexpr double bytes_per_gib = 1024.0 * 1024.0 * 1024.0;

// "23.5 GiB": how the refusals and `check` write an estimate and the usable memory, one decimal.
std::string gibibytes(std::uint64_t bytes);

}  // namespace heliostand
