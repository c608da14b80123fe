// Root-contact field, OpenCL vs reference, on a stand-sized root system: 12 × 12 tap-rooted conifers at
// 2 m spacing grown 15 years (≈ 10^5 segments). Two query sets: the growing apices of one year with 16
// moisture probes each (what grow_roots asks), and every segment end (a heavier, 10^5-apex case).
//   build/heliostand_benchmarks --benchmark_filter=RootField
#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

#include "compute/compute_backend.hpp"
#include "rng/random_stream.hpp"
#include "roots/make_root_field_solver.hpp"
#include "roots/reference_root_field_solver.hpp"
#include "roots/root_growth.hpp"

namespace {

using namespace heliostand;
using namespace heliostand::roots;

struct BenchmarkStand {
  SoilGrid soil{{{-13.0, -13.0, -3.0}, 0.25, {104, 104, 12}}, 1.0, 0.5};
  std::vector<RootSystem> trees;
  StandSegments segments;
  std::vector<RootTipQuery> apices, every_end;
  std::vector<glm::dvec3> apex_probes, end_probes;
};

const BenchmarkStand& stand() {
  static const std::unique_ptr<BenchmarkStand> built = [] {
    auto s = std::make_unique<BenchmarkStand>();
    for (int i = 0; i < 12; ++i)
      for (int j = 0; j < 12; ++j)
        s->trees.emplace_back(12 * i + j, glm::dvec3(-11.0 + 2.0 * i, -11.0 + 2.0 * j, 0.0), tap_rooted_conifer(), 0);
    std::vector<RootSystem*> pointers;
    for (RootSystem& tree : s->trees) pointers.push_back(&tree);
    ReferenceRootFieldSolver solver;
    for (int year = 1; year <= 15; ++year) {
      grow_roots(pointers, s->soil, solver, year, 2024);
      s->soil.recharge({});
    }
    s->segments = gather_segments(pointers);
    RandomStream random(7, {1});
    for (std::size_t t = 0; t < s->trees.size(); ++t)
      for (std::size_t i = 0; i < s->trees[t].segments().size(); ++i) {
        const RootSegment& segment = s->trees[t].segments()[i];
        RootTipQuery tip;
        tip.position = segment.end;
        tip.perception_radius_m = tap_rooted_conifer().of(segment.type).perception_radius_m;
        tip.excluded[0] = s->segments.offsets[t] + static_cast<int>(i);
        tip.excluded[1] = segment.parent >= 0 ? s->segments.offsets[t] + segment.parent : -1;
        const auto probes = draw_moisture_probes(random, 16);
        s->every_end.push_back(tip);
        s->end_probes.insert(s->end_probes.end(), probes.begin(), probes.end());
        if (segment.growing) {
          s->apices.push_back(tip);
          s->apex_probes.insert(s->apex_probes.end(), probes.begin(), probes.end());
        }
      }
    return s;
  }();
  return *built;
}

void run(benchmark::State& state, RootFieldSolver& solver, bool every_end) {
  const BenchmarkStand& s = stand();
  const RootFieldInput input{s.segments.lines, every_end ? s.every_end : s.apices,
                             every_end ? s.end_probes : s.apex_probes, 16, &s.soil};
  for (auto _ : state) benchmark::DoNotOptimize(solver.solve(input));
  state.counters["segments"] = static_cast<double>(s.segments.lines.size());
  state.counters["apices"] = static_cast<double>(input.tips.size());
  state.counters["apices_per_s"] = benchmark::Counter(static_cast<double>(input.tips.size()), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_RootField_Reference(benchmark::State& state) {
  ReferenceRootFieldSolver solver;
  run(state, solver, state.range(0) != 0);
}

void BM_RootField_OpenCL(benchmark::State& state) {
  if (!compute::opencl_device_exists()) {
    state.SkipWithError("no OpenCL device");
    return;
  }
  const auto solver = make_root_field_solver(compute::ComputeBackend::open({compute::DeviceChoice::Kind::opencl}));
  run(state, *solver, state.range(0) != 0);
}

BENCHMARK(BM_RootField_Reference)->ArgName("every_end")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_RootField_OpenCL)->ArgName("every_end")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
