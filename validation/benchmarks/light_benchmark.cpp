// Google Benchmark targets for the light kernel (heliostand_benchmarks). The side-by-side comparison with
// errors is `heliostand bench light` (docs/performance.md); these time single solver calls.
#include <benchmark/benchmark.h>

#include "compute/compute_backend.hpp"
#include "light/celestial_sphere.hpp"
#include "light/far_field.hpp"
#include "light/make_light_solver.hpp"
#include "light/near_field.hpp"
#include "light/occluders.hpp"
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

// The far field's host part, what every culled solve does before its table is swept: the density of the canopy's
// balls per cell and its clumping index, on the synthetic canopies of `heliostand bench light --balls N` (default
// parameters; 10^6 balls get coarser cells under the table's cap, as there).
void BM_FarFieldDensityAndClumping(benchmark::State& state) {
  const auto canopy = make_synthetic_canopy(static_cast<std::size_t>(state.range(0)), 1);
  LightParameters p;
  p.plot_x_max = p.plot_y_max = canopy.plot_size_m;
  const CelestialSphere sky(p);
  const OccluderSet set = make_occluder_set(canopy.balls, PlotTorus::from(p), p.cutoff_m);
  for (auto _ : state) benchmark::DoNotOptimize(FarField(set, p, sky, false).density());
  state.SetItemsProcessed(state.iterations() * state.range(0));  // balls per second
}

// The near-field search of a culled solve on the same canopies: the k-d tree, and every tile's candidate list laid
// out in shells (what `bench light` reports as search_seconds, less the lists' copy to the device).
void BM_NearFieldSearch(benchmark::State& state) {
  const auto canopy = make_synthetic_canopy(static_cast<std::size_t>(state.range(0)), 1);
  LightParameters p;
  const OccluderSet set = make_occluder_set(canopy.balls, PlotTorus::from(p), p.cutoff_m);
  std::vector<std::uint32_t> receivers(canopy.balls.size());
  for (std::uint32_t k = 0; k < receivers.size(); ++k) receivers[k] = k;
  for (auto _ : state) {
    const NearFieldSearch search(set, p.cutoff_m);
    benchmark::DoNotOptimize(search.tile_candidates(receivers, tile_edge_for(p.cutoff_m)).occluders.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));  // balls per second
}

BENCHMARK(BM_NearFieldSearch)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_FarFieldDensityAndClumping)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_OpenCLLightCulled)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_OpenCLLightExact)->Arg(1000)->Arg(4000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ReferenceLightExact)->Arg(500)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace heliostand
