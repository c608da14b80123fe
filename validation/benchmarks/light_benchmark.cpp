// Google Benchmark targets for the light kernel (heliostand_benchmarks). The side-by-side comparison with
// errors is `heliostand bench light` (docs/performance.md); these time single solver calls.
#include <benchmark/benchmark.h>

#include "light/opencl_light_solver.hpp"
#include "light/reference_light_solver.hpp"
#include "light/synthetic_canopy.hpp"

namespace heliostand {
namespace {

template <typename Solver>
void solve_canopy(benchmark::State& state, bool exact) {
  if constexpr (std::is_same_v<Solver, OpenCLLightSolver>) {
    if (!opencl_available()) {
      state.SkipWithError("no OpenCL device");
      return;
    }
  }
  const auto canopy = make_synthetic_canopy(static_cast<std::size_t>(state.range(0)), 1);
  LightParameters p;
  p.exact = exact;
  auto solver = [&] {
    if constexpr (std::is_same_v<Solver, OpenCLLightSolver>)
      return OpenCLLightSolver(p, std::nullopt);
    else
      return ReferenceLightSolver(p);
  }();
  for (auto _ : state) benchmark::DoNotOptimize(solver.solve(canopy.balls));
  state.SetItemsProcessed(state.iterations() * state.range(0));  // balls per second
  state.counters["candidates"] = solver.last_statistics().mean_candidates;
}

void BM_OpenCLLightCulled(benchmark::State& state) { solve_canopy<OpenCLLightSolver>(state, false); }
void BM_OpenCLLightExact(benchmark::State& state) { solve_canopy<OpenCLLightSolver>(state, true); }
void BM_ReferenceLightExact(benchmark::State& state) { solve_canopy<ReferenceLightSolver>(state, true); }

BENCHMARK(BM_OpenCLLightCulled)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_OpenCLLightExact)->Arg(1000)->Arg(4000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ReferenceLightExact)->Arg(500)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace heliostand
