#pragma once
// `heliostand bench light`: times the light solvers side by side on reproducible synthetic canopies, and on real
// stands' canopies handed in by the caller, and measures each one's error against the reference exact solution.
// Results are JSON (docs/performance.md).
#include <cstdint>
#include <string>
#include <vector>

#include "light/leaf_ball.hpp"
#include "light/light_parameters.hpp"

namespace heliostand {

struct LightBenchmarkOptions {
  std::vector<std::size_t> ball_counts{1000, 10000, 100000};
  std::uint64_t seed = 1;
  std::string opencl_device = "opencl";   // the OpenCL rows need a device; "none" skips them
  LightParameters parameters;             // culled-mode parameters (exact runs set exact = true)
  // Above these sizes a solver is run on an evenly spaced subsample of balls only and its full-stand time is
  // extrapolated (each ball's answer is independent of the others, so the subsample answers are exact).
  std::size_t reference_exact_max = 4000;
  std::size_t reference_culled_max = 30000;
  std::size_t opencl_exact_max = 20000;
  std::size_t subsample = 400;            // balls in the subsample (also where errors are measured)
  // Evaluations of the OpenCL culled + far-field solver (the default), one after another with one solver. The first
  // is the row's; the later ones, as every year after the first of a run, find the buffers the solver keeps on its
  // device already made (and the memory under them already touched) and are listed after it.
  std::size_t evaluations = 1;
};

// A real stand's canopy as the light solver sees it. The light module does not know stands: the caller
// (run/established_canopy.hpp) establishes one and hands over its leaf balls and its light parameters.
struct LightBenchmarkStand {
  std::string name;              // what the JSON row calls it (the scenario file)
  std::vector<LeafBall> balls;   // every living tree's leaf balls
  std::size_t tree_count = 0;    // the living trees they belong to
  LightParameters parameters;    // the stand's own (its [light], the plot as the periodic domain)
};

// The memory the benchmark may need for a synthetic canopy of `ball_count` leaf balls lit with `p`, estimated before it
// is made so that a count far beyond the machine is refused with the figures (cli/bench_command.cpp) instead of growing
// until the OOM killer ends it:
//
//   estimate = 1 GiB + ball_count × 2 KiB + 2 × (p.far_field_table_mb − 512 MB, where above)
//
// Measured peaks of `bench light --balls N --subsample 20` with every solver but the default one on the subsample
// (docs/performance.md "Memory"): 637 MiB at 10⁵ balls, 2 217 MiB at 10⁶, about 1.8 kB a ball above some 460 MiB,
// both rounded up; the far-field table's cap beyond its default as a run's estimate counts it
// (far_field_table_bytes_beyond_default). Like a run's estimate (stand/memory_estimate.hpp) it catches a count ten
// times too large, or a cap no machine here holds, not a tight budget. Saturates at the largest std::uint64_t.
std::uint64_t synthetic_canopy_memory_bytes(std::size_t ball_count, const LightParameters& p);

// The estimate's formula in words, from the same constants ("1 GiB + 2 KiB a ball[ + twice the far-field table's cap
// above 512 MB]", the last where p's cap is above it), for the refusal.
std::string synthetic_canopy_memory_formula(const LightParameters& p);

// Runs the benchmark on the synthetic canopies of `options.ball_counts` (with `options.parameters`), then on each
// of `stands` (with its own parameters), and returns the JSON report; progress goes to spdlog (stderr).
std::string run_light_benchmark(const LightBenchmarkOptions& options, const std::vector<LightBenchmarkStand>& stands = {});

}  // namespace heliostand
