// Google Benchmark targets for the light kernel (heliostand_benchmarks). The side-by-side comparison with
// errors is `heliostand bench light` (docs/performance.md); these time single solver calls.
#include <benchmark/benchmark.h>

#include "compute/compute_backend.hpp"
#include "light/make_light_solver.hpp"
#include "light/synthetic_canopy.hpp"

namespace heliostand {
namespace {

using compute::DeviceChoice;

void solve_canopy(benchmark::State& state, DeviceChoice::Kind device, bool exact) {
  if (device == DeviceChoice::Kind::opencl && !compute::opencl_device_exists()) {
    state.SkipWithError("no OpenCL device");
    return;
  }
  const auto canopy = make_synthetic_canopy(static_cast<std::size_t>(state.range(0)), 1);
  LightParameters p;
  p.exact = exact;
  const auto solver = make_light_solver(compute::ComputeBackend::open({device}), p);
  for (auto _ : state) benchmark::DoNotOptimize(solver->solve(canopy.balls));
  state.SetItemsProcessed(state.iterations() * state.range(0));  // balls per second
  state.counters["candidates"] = solver->last_statistics().mean_candidates;
}

void BM_OpenCLLightCulled(benchmark::State& state) { solve_canopy(state, DeviceChoice::Kind::opencl, false); }
void BM_OpenCLLightExact(benchmark::State& state) { solve_canopy(state, DeviceChoice::Kind::opencl, true); }
void BM_ReferenceLightExact(benchmark::State& state) { solve_canopy(state, DeviceChoice::Kind::reference, true); }

BENCHMARK(BM_OpenCLLightCulled)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_OpenCLLightExact)->Arg(1000)->Arg(4000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ReferenceLightExact)->Arg(500)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace heliostand
