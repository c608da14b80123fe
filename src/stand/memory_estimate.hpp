#pragma once
// How much memory a run will need, estimated before it starts, so that a scenario far beyond the machine is
// refused up front with the estimate instead of dying hours later (or taking the machine down with it).
//
//   estimate = 1 GiB + trees × 1.75 MiB
//
// 1 GiB: what a run holds whatever its size (program and libraries, the OpenCL runtime, the light's far-field
// table at its default 512 MB cap). 1.75 MiB per tree: the largest per-tree figure measured (docs/performance.md:
// the hectare, 2 500 trees grown to age 80, peaked at 4.3 GB: (4.3 GB − 1 GiB) / 2 500 ≈ 1.3 MiB, rounded up by a
// third for older and bigger trees). Since the OpenCL solver keeps the table's second layout too (2026-11-28), the
// hectare peaks at 4.8 GB, (4.8 GB − 1 GiB) / 2 500 ≈ 1.5 MiB a tree: still within the formula. It is meant to catch
// a survey ten times too large, not to budget tightly: a run is refused only when the estimate exceeds the memory it
// may use.
#include <cstdint>
#include <string>

namespace heliostand {

struct Scenario;

struct MemoryEstimate {
  std::uint64_t bytes = 0;
  std::size_t trees = 0;
};

MemoryEstimate estimate_run_memory(const Scenario& scenario);

// Throws InputError (the scenario's file, key 'stand.survey') when `estimate` exceeds `usable`, with both figures
// and the formula.
void refuse_beyond_memory(const Scenario& scenario, const MemoryEstimate& estimate, std::uint64_t usable);

// `scenario`'s estimate refused when it exceeds the memory this process may use (core/usable_memory.hpp; nothing is
// refused when that cannot be read): what `grow`, `bench stand` and `bench light --stand` do before any work.
void refuse_run_beyond_this_machine(const Scenario& scenario);

}  // namespace heliostand
