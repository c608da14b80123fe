#pragma once
// How much memory a run will need, estimated before it starts, so that a scenario far beyond the machine is
// refused up front with the estimate instead of dying hours later (or taking the machine down with it).
//
//   estimate = 1 GiB + trees × 1.75 MiB + 2 × (light.far_field_table_mb − 512 MB, where above)
//
// 1 GiB: what a run holds whatever its size (program and libraries, the OpenCL runtime, the light's far-field
// table at its default 512 MB cap). 1.75 MiB per tree: the largest per-tree figure measured (docs/performance.md:
// the hectare, 2 500 trees grown to age 80, peaked at 4.3 GB: (4.3 GB − 1 GiB) / 2 500 ≈ 1.3 MiB, rounded up by a
// third for older and bigger trees). Since the OpenCL solver keeps the table's second layout too (2026-11-28), the
// hectare peaks at 4.8 GB, (4.8 GB − 1 GiB) / 2 500 ≈ 1.5 MiB a tree: still within the formula. A far-field table
// allowed more than its default may take it, twice over (the OpenCL solver's two layouts of it; an upper bound since
// 2026-12-05, when the sweep's layout came to hold a chunk of patches' share of the table): stands/tiny in
// 0.05 m cells peaked at 5.1 GiB under a 3 000 MB cap and at 1.0 GiB under 512 MB, 1.77 bytes a byte of the cap
// (docs/performance.md "Memory"). It is meant to catch a survey ten times too large, or a cap no machine here holds,
// not to budget tightly: a run is refused only when the estimate exceeds the memory it may use.
#include <cstdint>
#include <optional>
#include <string>

namespace heliostand {

struct Scenario;

struct MemoryEstimate {
  std::uint64_t bytes = 0;
  std::size_t trees = 0;
  std::uint64_t far_field_table_bytes = 0;  // the table's share beyond its default cap (0 at or below it)
};

MemoryEstimate estimate_run_memory(const Scenario& scenario);

// Why `estimate` exceeds `usable` because of the far-field table's cap: the reason (the cap, the estimate, the
// formula, the usable memory, what to do) where the stand would fit without the table's share; std::nullopt where the
// run fits, or where the stand alone does not. `bench light --far-field-table-mb` names its flag with it.
std::optional<std::string> far_field_table_beyond_memory(const Scenario& scenario, const MemoryEstimate& estimate,
                                                         std::uint64_t usable);

// Throws InputError when `estimate` exceeds `usable`, with both figures and the formula: under the key
// 'light.far_field_table_mb' where the stand would fit without the table's share, else 'stand.survey'.
void refuse_beyond_memory(const Scenario& scenario, const MemoryEstimate& estimate, std::uint64_t usable);

// `scenario`'s estimate refused when it exceeds the memory this process may use (core/usable_memory.hpp; nothing is
// refused when that cannot be read): what `grow`, `bench stand` and `bench light --stand` do before any work.
void refuse_run_beyond_this_machine(const Scenario& scenario);

}  // namespace heliostand
