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
#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include "core/json_text.hpp"
#include "core/page_settings.hpp"
#include "core/processor.hpp"
#include "core/seconds_since.hpp"
#include "core/usable_memory.hpp"
#include "geometry/angles.hpp"
#include "light/far_field_buffers.hpp"
#include "light/make_light_solver.hpp"
#include "light/synthetic_canopy.hpp"

namespace heliostand {
namespace {

using Clock = std::chrono::steady_clock;
using Json = nlohmann::ordered_json;  // fields in the order written

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

Json times_json(const Run& run) {
  return {{"seconds", run.seconds},
          {"setup_seconds", run.setup_seconds},
          {"search_seconds", run.search_seconds},
          {"far_field_seconds", run.far_field_seconds}};
}

Json run_json(const Run& run, const Run& truth) {
  if (!run.ran) return nullptr;
  Json json = times_json(run);
  json["far_field_cell_m"] = run.far_field_cell_m;
  json["estimated_from_subsample"] = run.estimated;
  if (&run != &truth && truth.ran) {
    const Error e = error_against(truth.at_subsample, run.at_subsample);
    json["error_vs_reference_exact"] = {{"mean_abs_light", e.mean_abs_light},
                                        {"max_abs_light", e.max_abs_light},
                                        {"mean_light_bias", e.mean_light_bias},
                                        {"mean_angle_degrees", e.mean_angle_degrees}};
  }
  if (!run.later.empty()) {
    Json later = Json::array();
    for (const Run& evaluation : run.later) later.push_back(times_json(evaluation));
    json["later_evaluations"] = std::move(later);
  }
  return json;
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

Json ratio(const Run& slow, const Run& fast) {
  if (!slow.ran || !fast.ran || fast.seconds <= 0) return nullptr;
  return slow.seconds / fast.seconds;
}

const char* sky_name(LightParameters::Sky sky) {
  return sky == LightParameters::Sky::kanamaru ? "kanamaru" : "overcast";
}

Json parameters_json(const LightParameters& p) {
  return {{"sky", sky_name(p.sky)},
          {"sky_scale", p.sky_scale},
          {"sky_bands", p.sky_bands},
          {"sky_sectors", p.sky_sectors},
          {"transmittance", p.transmittance},
          {"intensity_ratio", p.intensity_ratio},
          {"cutoff_m", p.cutoff_m},
          {"far_field_cell_m", p.far_field_cell_m},
          {"far_field_table_mb", p.far_field_table_mb},
          {"far_field_bias_correction", p.far_field_bias_correction},
          {"far_field_hand_over_cells", p.far_field_hand_over_cells},
          {"periodic", p.periodic}};
}

// The four solvers on one canopy -- the culled ones with `parameters`, the exact ones with the same but exact --
// added to its row as the fields from "opencl_device" on.
void add_solver_fields(Json& row, const LightBenchmarkOptions& options, const std::vector<LeafBall>& balls,
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
    // Warm-up: compiles the kernels for a small grid. PoCL compiles a large grid's forms apart, at the first launch of
    // one, so a first timed solve into an empty kernel cache still pays for those (docs/performance.md "A fourth
    // machine started anew, and PoCL's large-grid kernels compiled at a first solve").
    (void)culled_solver->solve(std::span(balls).first(std::min<std::size_t>(balls.size(), 64)));
    opencl_exact = time_solver("opencl exact", *exact_solver, balls, subsample, options.opencl_exact_max);
    opencl_culled = time_solver("opencl culled+far-field", *culled_solver, balls, subsample, balls.size());
    time_later_evaluations(opencl_culled, *culled_solver, balls, subsample, balls.size(), options.evaluations);
  }
  const bool whole = balls.size() <= options.reference_exact_max;
  row["opencl_device"] = device;
  row["build_seconds"] = opencl_culled.ran ? opencl_culled.setup_seconds : reference_culled.setup_seconds;
  row["mean_candidates"] = reference_culled.mean_candidates;
  row["mean_tile_candidates"] = reference_culled.mean_tile_candidates;
  row["error_measured_on"] = {{"balls", whole ? balls.size() : subsample.size()}, {"whole_stand", whole}};
  row["reference_exact"] = run_json(reference_exact, reference_exact);
  row["reference_culled"] = run_json(reference_culled, reference_exact);
  row["opencl_exact"] = run_json(opencl_exact, reference_exact);
  row["opencl_culled_far_field"] = run_json(opencl_culled, reference_exact);
  row["speedup"] = {{"opencl_exact_over_reference_exact", ratio(reference_exact, opencl_exact)},
                    {"opencl_culled_over_opencl_exact", ratio(opencl_exact, opencl_culled)},
                    {"opencl_culled_over_reference_exact", ratio(reference_exact, opencl_culled)},
                    {"reference_culled_over_reference_exact", ratio(reference_exact, reference_culled)}};
}

Json synthetic_row(const LightBenchmarkOptions& options, std::size_t ball_count) {
  const SyntheticCanopy canopy = make_synthetic_canopy(ball_count, options.seed);
  LightParameters parameters = options.parameters;
  parameters.plot_x_min = parameters.plot_y_min = 0;
  parameters.plot_x_max = parameters.plot_y_max = canopy.plot_size_m;
  Json row = {{"balls", canopy.balls.size()}, {"trees", canopy.tree_count}, {"plot_m", canopy.plot_size_m}};
  add_solver_fields(row, options, canopy.balls, parameters);
  return row;
}

// A real stand's row: the synthetic rows' fields, plus the stand's name, plot and own light parameters.
Json stand_row(const LightBenchmarkOptions& options, const LightBenchmarkStand& stand) {
  const LightParameters& p = stand.parameters;
  const double width = p.plot_x_max - p.plot_x_min, depth = p.plot_y_max - p.plot_y_min;
  Json row = {{"stand", stand.name},
              {"balls", stand.balls.size()},
              {"trees", stand.tree_count},
              {"plot_m", width == depth ? Json(width) : Json()},  // null for a plot that is not square
              {"plot_bounds_m", {p.plot_x_min, p.plot_y_min, p.plot_x_max, p.plot_y_max}},
              {"parameters", parameters_json(p)}};
  add_solver_fields(row, options, stand.balls, p);
  return row;
}

// The synthetic canopy's memory estimate (light_benchmark.hpp): a fixed part and a part per leaf ball.
constexpr double canopy_fixed_bytes = 1.0 * bytes_per_gib, canopy_bytes_per_ball = 2048.0;

}  // namespace

std::uint64_t synthetic_canopy_memory_bytes(std::size_t ball_count, const LightParameters& p) {
  const double bytes = canopy_fixed_bytes + canopy_bytes_per_ball * static_cast<double>(ball_count) +
                       far_field_table_bytes_beyond_default(p);
  constexpr auto largest = std::numeric_limits<std::uint64_t>::max();
  return bytes >= static_cast<double>(largest) ? largest : static_cast<std::uint64_t>(bytes);
}

std::string synthetic_canopy_memory_formula(const LightParameters& p) {
  return fmt::format("{:g} GiB + {:g} KiB a ball{}", canopy_fixed_bytes / bytes_per_gib,
                     canopy_bytes_per_ball / 1024.0,
                     far_field_table_bytes_beyond_default(p) > 0 ? " + " + far_field_table_memory_term() : "");
}

std::string run_light_benchmark(const LightBenchmarkOptions& options, const std::vector<LightBenchmarkStand>& stands) {
  Json json;
  json["benchmark"] = "light";
  json["seed"] = options.seed;
  json["hardware_threads"] = std::thread::hardware_concurrency();
  json["processor"] = processor_json(this_processor());
  json["pages"] = page_settings_json(this_process_page_settings());  // the allocator's settings the seconds are of
  json["parameters"] = parameters_json(options.parameters);
  json["limits"] = {{"reference_exact_max", options.reference_exact_max},
                    {"reference_culled_max", options.reference_culled_max},
                    {"opencl_exact_max", options.opencl_exact_max},
                    {"subsample", options.subsample}};
  json["note"] = "above a solver's limit its time is extrapolated from an evenly spaced subsample of balls (setup + "
                 "per-ball time x N / subsample); errors are measured on that subsample against reference exact; the "
                 "synthetic stands use these parameters, a real stand (\"stand\") its own";
  Json rows = Json::array();
  for (std::size_t ball_count : options.ball_counts) rows.push_back(synthetic_row(options, ball_count));
  for (const LightBenchmarkStand& stand : stands) rows.push_back(stand_row(options, stand));
  json["stands"] = std::move(rows);
  // A NaN or infinite figure is written as null, and a stand's name in a legacy encoding with its invalid bytes
  // replaced: the JSON stays valid whatever a run measured.
  return json_text(json);
}

}  // namespace heliostand
