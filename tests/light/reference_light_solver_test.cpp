// The reference solver (the oracle) lights its receivers on the worker threads. Each sample must be what one
// thread computes, bit for bit, on any number of threads: exact and culled (near field, far field), open plot and
// torus, the whole stand and a subset of receivers.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "core/parallel_for.hpp"
#include "light/reference_light_solver.hpp"
#include "light/synthetic_canopy.hpp"

namespace heliostand {
namespace {

struct Lit {
  std::vector<LightSample> samples;
  double mean_candidates = 0;
  double mean_tile_candidates = 0;
};

Lit light_on(unsigned threads, const LightParameters& p, const std::vector<LeafBall>& balls,
             const std::vector<std::uint32_t>& receivers) {
  set_worker_threads(threads);
  ReferenceLightSolver solver(p);
  Lit lit;
  lit.samples = solver.solve_for(balls, receivers);
  lit.mean_candidates = solver.last_statistics().mean_candidates;
  lit.mean_tile_candidates = solver.last_statistics().mean_tile_candidates;
  return lit;
}

class ReferenceLightSolverThreads : public ::testing::TestWithParam<std::tuple<bool, bool>> {
 protected:
  ~ReferenceLightSolverThreads() override { set_worker_threads(0); }
};

TEST_P(ReferenceLightSolverThreads, TheSameLightOnAnyNumberOfThreads) {
  const auto [exact, periodic] = GetParam();
  const SyntheticCanopy canopy = make_synthetic_canopy(exact ? 300 : 1500, 5);
  LightParameters p;
  p.exact = exact;
  p.cutoff_m = 2.0;  // a near field of a few dozen balls and a far field beyond it
  p.periodic = periodic;
  p.plot_x_min = p.plot_y_min = 0.0;
  p.plot_x_max = p.plot_y_max = canopy.plot_size_m;
  std::vector<std::uint32_t> receivers;
  for (std::uint32_t k = 0; k < canopy.balls.size(); k += 3) receivers.push_back(k);  // a subset, out of step

  const Lit in_order = light_on(1, p, canopy.balls, receivers);
  ASSERT_EQ(in_order.samples.size(), receivers.size());
  int shaded = 0;
  for (const LightSample& sample : in_order.samples) shaded += sample.light < 0.999 ? 1 : 0;
  ASSERT_GT(shaded, int(receivers.size()) / 2) << "a canopy that shades most of its balls";
  for (unsigned threads : {2u, 3u, 8u}) {
    const Lit lit = light_on(threads, p, canopy.balls, receivers);
    ASSERT_EQ(lit.samples.size(), in_order.samples.size());
    int differing = 0;
    for (std::size_t k = 0; k < lit.samples.size(); ++k)
      differing += lit.samples[k].light != in_order.samples[k].light ||
                   lit.samples[k].vector != in_order.samples[k].vector;
    EXPECT_EQ(differing, 0) << threads << " threads";
    EXPECT_EQ(lit.mean_candidates, in_order.mean_candidates) << threads << " threads";
    EXPECT_EQ(lit.mean_tile_candidates, in_order.mean_tile_candidates) << threads << " threads";
  }
}

INSTANTIATE_TEST_SUITE_P(ExactAndCulled, ReferenceLightSolverThreads,
                         ::testing::Combine(::testing::Bool(), ::testing::Bool()),
                         [](const auto& info) {
                           return std::string(std::get<0>(info.param) ? "Exact" : "Culled") +
                                  (std::get<1>(info.param) ? "Periodic" : "Open");
                         });

}  // namespace
}  // namespace heliostand
