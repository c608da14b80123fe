#include "light/light_benchmark.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <stdexcept>
#include <thread>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <spdlog/spdlog.h>

#include "core/json_string.hpp"
#include "core/processor.hpp"
#include "core/seconds_since.hpp"
#include "core/usable_memory.hpp"
#include "geometry/angles.hpp"
#include "light/make_light_solver.hpp"
#include "light/synthetic_canopy.hpp"

namespace heliostand {
namespace {

using Clock = std::chrono::steady_clock;

struct Run {
  std::string name;
  bool ran = false;
  bool estimated = false;       // time extrapolated from the subsample
  double seconds = 0;           // one evaluation of the whole stand (setup included)
  double setup_seconds = 0;
  double search_seconds = 0;     // parts of setup_seconds: candidate search, far-field table
  double far_field_seconds = 0;
  double far_field_cell_m = 0;   // the far field's cell edge (coarser than asked when the table hit its cap)
  double mean_candidates = 0;
  double mean_tile_candidates = 0;
  std::vector<LightSample> at_subsample;  // answers at the error-measurement balls
  std::vector<Run> later;                 // later evaluations by the same solver (LightBenchmarkOptions::evaluations)
};

struct Error {
  double mean_abs_light = 0, max_abs_light = 0, mean_angle_degrees = 0;
  double mean_light_bias = 0;  // mean (test - truth): negative = too dark
};

Error error_against(const std::vector<LightSample>& truth, const std::vector<LightSample>& test) {
  Error e;
  std::size_t angles = 0;
  for (std::size_t k = 0; k < truth.size(); ++k) {
    const double diff = std::abs(truth[k].light - test[k].light);
    e.mean_abs_light += diff;
    e.mean_light_bias += test[k].light - truth[k].light;
    e.max_abs_light = std::max(e.max_abs_light, diff);
    // a balanced sky has no vector; such balls carry no direction error
    if (glm::length(truth[k].vector) > 0 && glm::length(test[k].vector) > 0) {
      e.mean_angle_degrees += degrees(std::acos(std::clamp(glm::dot(truth[k].vector, test[k].vector), -1.0, 1.0)));
      ++angles;
    }
  }
  if (!truth.empty()) {
    e.mean_abs_light /= truth.size();
    e.mean_light_bias /= truth.size();
  }
  if (angles > 0) e.mean_angle_degrees /= angles;
  return e;
}

// Times `solver` on the whole stand, or on the subsample when the stand exceeds `max_balls`.
Run time_solver(const std::string& name, LightSolver& solver, const std::vector<LeafBall>& balls,
                const std::vector<std::uint32_t>& subsample, std::size_t max_balls) {
  Run run;
  run.name = name;
  run.ran = true;
  spdlog::info("bench light: {} balls, {} ({})", balls.size(), name,
               balls.size() <= max_balls ? "whole stand" : fmt::format("subsample of {}", subsample.size()));
  if (balls.size() <= max_balls) {
    const auto start = Clock::now();
    const auto all = solver.solve(balls);
    run.seconds = seconds_since(start);
    for (auto k : subsample) run.at_subsample.push_back(all[k]);
  } else {
    run.estimated = true;
    const auto start = Clock::now();
    run.at_subsample = solver.solve_for(balls, subsample);
    const double wall = seconds_since(start);
    const auto& stats = solver.last_statistics();
    // setup (tree, far field) is per stand; the per-ball part scales with the number of balls
    run.seconds = stats.setup_seconds + (wall - stats.setup_seconds) * double(balls.size()) / subsample.size();
  }
  run.setup_seconds = solver.last_statistics().setup_seconds;
  run.search_seconds = solver.last_statistics().search_seconds;
  run.far_field_seconds = solver.last_statistics().far_field_seconds;
  run.far_field_cell_m = solver.last_statistics().far_field_cell_m;
  run.mean_candidates = solver.last_statistics().mean_candidates;
  run.mean_tile_candidates = solver.last_statistics().mean_tile_candidates;
  spdlog::info("bench light: {} balls, {}: {:.3f} s{}", balls.size(), name, run.seconds,
               run.estimated ? " (estimated)" : "");
  return run;
}

std::string times_json(const Run& run) {
  return fmt::format(R"({{"seconds": {:.6g}, "setup_seconds": {:.6g}, "search_seconds": {:.6g}, )"
                     R"("far_field_seconds": {:.6g})",
                     run.seconds, run.setup_seconds, run.search_seconds, run.far_field_seconds);
}

std::string run_json(const Run& run, const Run& truth) {
  if (!run.ran) return "null";
  std::string text = times_json(run) + fmt::format(R"(, "far_field_cell_m": {:.6g}, "estimated_from_subsample": {})",
                                                   run.far_field_cell_m, run.estimated ? "true" : "false");
  if (&run != &truth && truth.ran) {
    const Error e = error_against(truth.at_subsample, run.at_subsample);
    text += fmt::format(R"(, "error_vs_reference_exact": {{"mean_abs_light": {:.6g}, "max_abs_light": {:.6g}, )"
                        R"("mean_light_bias": {:.6g}, "mean_angle_degrees": {:.6g}}})",
                        e.mean_abs_light, e.max_abs_light, e.mean_light_bias, e.mean_angle_degrees);
  }
  if (!run.later.empty()) {
    text += R"(, "later_evaluations": [)";
    for (std::size_t k = 0; k < run.later.size(); ++k) text += (k > 0 ? ", " : "") + times_json(run.later[k]) + "}";
    text += "]";
  }
  return text + "}";
}

// `evaluations - 1` more evaluations of `run`'s solver on the same balls. Each must light the subsample as the
// first did, bit for bit: a solver's kept buffers are reused, never read before they are written.
void time_later_evaluations(Run& run, LightSolver& solver, const std::vector<LeafBall>& balls,
                            const std::vector<std::uint32_t>& subsample, std::size_t max_balls,
                            std::size_t evaluations) {
  for (std::size_t k = 1; k < evaluations; ++k) {
    Run later = time_solver(run.name + fmt::format(" (evaluation {})", k + 1), solver, balls, subsample, max_balls);
    for (std::size_t b = 0; b < subsample.size(); ++b)
      if (later.at_subsample[b].light != run.at_subsample[b].light ||
          later.at_subsample[b].vector != run.at_subsample[b].vector)
        throw std::runtime_error(fmt::format("bench light: evaluation {} of {} lit ball {} differently from the first",
                                             k + 1, run.name, subsample[b]));
    later.at_subsample.clear();
    run.later.push_back(std::move(later));
  }
}

std::string ratio(const Run& slow, const Run& fast) {
  if (!slow.ran || !fast.ran || fast.seconds <= 0) return "null";
  return fmt::format("{:.4g}", slow.seconds / fast.seconds);
}

const char* sky_name(LightParameters::Sky sky) {
  return sky == LightParameters::Sky::kanamaru ? "kanamaru" : "overcast";
}

std::string parameters_json(const LightParameters& p) {
  return fmt::format(R"({{"sky": "{}", "sky_scale": {}, "sky_bands": {}, "sky_sectors": {}, "transmittance": {}, )"
                     R"("intensity_ratio": {}, "cutoff_m": {}, "far_field_cell_m": {}, "far_field_bias_correction": {}, )"
                     R"("far_field_hand_over_cells": {}, "periodic": {}}})",
                     sky_name(p.sky), p.sky_scale, p.sky_bands, p.sky_sectors, p.transmittance, p.intensity_ratio,
                     p.cutoff_m, p.far_field_cell_m, p.far_field_bias_correction, p.far_field_hand_over_cells,
                     p.periodic ? "true" : "false");
}

// The four solvers on one canopy -- the culled ones with `parameters`, the exact ones with the same but exact --
// as the fields of its row from "opencl_device" on.
std::string solver_rows(const LightBenchmarkOptions& options, const std::vector<LeafBall>& balls,
                        const LightParameters& parameters) {
  std::vector<std::uint32_t> subsample;
  const std::size_t k_count = std::min(options.subsample, balls.size());
  for (std::size_t k = 0; k < k_count; ++k) subsample.push_back(static_cast<std::uint32_t>(k * balls.size() / k_count));

  LightParameters culled = parameters;
  culled.exact = false;
  LightParameters exact = culled;
  exact.exact = true;

  const auto reference = compute::ComputeBackend::reference();
  auto reference_exact_solver = make_light_solver(reference, exact);
  auto reference_culled_solver = make_light_solver(reference, culled);
  Run reference_exact = time_solver("reference exact", *reference_exact_solver, balls, subsample, options.reference_exact_max);
  Run reference_culled = time_solver("reference culled", *reference_culled_solver, balls, subsample, options.reference_culled_max);
  Run opencl_exact, opencl_culled;
  std::string device = "none";
  if (options.opencl_device != "none") {
    const auto opencl = compute::ComputeBackend::open(compute::DeviceChoice::parse(options.opencl_device));
    auto exact_solver = make_light_solver(opencl, exact);
    auto culled_solver = make_light_solver(opencl, culled);
    device = culled_solver->name();
    (void)culled_solver->solve(std::span(balls).first(std::min<std::size_t>(balls.size(), 64)));  // warm-up
    opencl_exact = time_solver("opencl exact", *exact_solver, balls, subsample, options.opencl_exact_max);
    opencl_culled = time_solver("opencl culled+far-field", *culled_solver, balls, subsample, balls.size());
    time_later_evaluations(opencl_culled, *culled_solver, balls, subsample, balls.size(), options.evaluations);
  }
  const bool whole = balls.size() <= options.reference_exact_max;
  return fmt::format(
      R"("opencl_device": "{}",)"
      "\n"
      R"(     "build_seconds": {:.6g}, "mean_candidates": {:.6g}, "mean_tile_candidates": {:.6g},)"
      "\n"
      R"(     "error_measured_on": {{"balls": {}, "whole_stand": {}}},)"
      "\n"
      R"(     "reference_exact": {},)"
      "\n"
      R"(     "reference_culled": {},)"
      "\n"
      R"(     "opencl_exact": {},)"
      "\n"
      R"(     "opencl_culled_far_field": {},)"
      "\n"
      R"(     "speedup": {{"opencl_exact_over_reference_exact": {}, "opencl_culled_over_opencl_exact": {}, )"
      R"("opencl_culled_over_reference_exact": {}, "reference_culled_over_reference_exact": {}}}}})",
      device, opencl_culled.ran ? opencl_culled.setup_seconds : reference_culled.setup_seconds,
      reference_culled.mean_candidates, reference_culled.mean_tile_candidates,
      whole ? balls.size() : subsample.size(), whole ? "true" : "false",
      run_json(reference_exact, reference_exact), run_json(reference_culled, reference_exact),
      run_json(opencl_exact, reference_exact), run_json(opencl_culled, reference_exact),
      ratio(reference_exact, opencl_exact), ratio(opencl_exact, opencl_culled), ratio(reference_exact, opencl_culled),
      ratio(reference_exact, reference_culled));
}

std::string synthetic_row(const LightBenchmarkOptions& options, std::size_t ball_count) {
  const SyntheticCanopy canopy = make_synthetic_canopy(ball_count, options.seed);
  LightParameters parameters = options.parameters;
  parameters.plot_x_min = parameters.plot_y_min = 0;
  parameters.plot_x_max = parameters.plot_y_max = canopy.plot_size_m;
  return fmt::format(R"(    {{"balls": {}, "trees": {}, "plot_m": {:.4g}, )", canopy.balls.size(), canopy.tree_count,
                     canopy.plot_size_m) +
         solver_rows(options, canopy.balls, parameters);
}

// A real stand's row: the synthetic rows' fields, plus the stand's name, plot and own light parameters.
std::string stand_row(const LightBenchmarkOptions& options, const LightBenchmarkStand& stand) {
  const LightParameters& p = stand.parameters;
  const double width = p.plot_x_max - p.plot_x_min, depth = p.plot_y_max - p.plot_y_min;
  return fmt::format(R"(    {{"stand": {}, "balls": {}, "trees": {}, "plot_m": {}, )"
                     R"("plot_bounds_m": [{:.6g}, {:.6g}, {:.6g}, {:.6g}],)"
                     "\n"
                     R"(     "parameters": {},)"
                     "\n     ",
                     json_string(stand.name), stand.balls.size(), stand.tree_count,
                     width == depth ? fmt::format("{:.4g}", width) : "null", p.plot_x_min, p.plot_y_min,
                     p.plot_x_max, p.plot_y_max, parameters_json(p)) +
         solver_rows(options, stand.balls, p);
}

// The synthetic canopy's memory estimate (light_benchmark.hpp): a fixed part and a part per leaf ball.
constexpr double canopy_fixed_bytes = 1.0 * bytes_per_gib, canopy_bytes_per_ball = 2048.0;

}  // namespace

std::uint64_t synthetic_canopy_memory_bytes(std::size_t ball_count) {
  const double bytes = canopy_fixed_bytes + canopy_bytes_per_ball * static_cast<double>(ball_count);
  constexpr auto largest = std::numeric_limits<std::uint64_t>::max();
  return bytes >= static_cast<double>(largest) ? largest : static_cast<std::uint64_t>(bytes);
}

std::string synthetic_canopy_memory_formula() {
  return fmt::format("{:g} GiB + {:g} KiB a ball", canopy_fixed_bytes / bytes_per_gib, canopy_bytes_per_ball / 1024.0);
}

std::string run_light_benchmark(const LightBenchmarkOptions& options, const std::vector<LightBenchmarkStand>& stands) {
  std::string text = fmt::format(
      R"({{"benchmark": "light", "seed": {}, "hardware_threads": {}, "processor": {},)"
      "\n"
      R"( "parameters": {},)"
      "\n"
      R"( "limits": {{"reference_exact_max": {}, "reference_culled_max": {}, "opencl_exact_max": {}, "subsample": {}}},)"
      "\n"
      R"( "note": "above a solver's limit its time is extrapolated from an evenly spaced subsample of balls (setup + per-ball time x N / subsample); errors are measured on that subsample against reference exact; the synthetic stands use these parameters, a real stand (\"stand\") its own",)"
      "\n"
      R"( "stands": [)"
      "\n",
      options.seed, std::thread::hardware_concurrency(), processor_json(this_processor()),
      parameters_json(options.parameters), options.reference_exact_max, options.reference_culled_max,
      options.opencl_exact_max, options.subsample);
  std::vector<std::string> rows;
  for (std::size_t ball_count : options.ball_counts) rows.push_back(synthetic_row(options, ball_count));
  for (const LightBenchmarkStand& stand : stands) rows.push_back(stand_row(options, stand));
  for (std::size_t k = 0; k < rows.size(); ++k) text += rows[k] + (k + 1 < rows.size() ? ",\n" : "\n");
  return text + " ]}\n";
}

}  // namespace heliostand
