#include "cli/bench_command.hpp"

#include <cstdint>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/number_checks.hpp"
#include "cli/path_checks.hpp"
#include "cli/seed_option.hpp"
#include "compute/compute_backend.hpp"
#include "compute/device_choice.hpp"
#include "core/usable_memory.hpp"
#include "io/output_folder.hpp"
#include "light/far_field_buffers.hpp"
#include "light/light_benchmark.hpp"
#include "run/established_canopy.hpp"
#include "run/stand_benchmark.hpp"
#include "scenario/scenario.hpp"
#include "scenario/scenario_limits.hpp"
#include "stand/memory_estimate.hpp"

namespace heliostand::cli {
namespace {

// The file first, under a temporary name renamed into place (a FIFO or a device written in place: AtomicFile), then
// stdout: a file that cannot be written leaves neither a half-written file nor a report on stdout that the exit
// status calls failed.
void print_json(const std::string& json, const std::string& output) {
  if (!output.empty()) {
    AtomicFile file(output);
    file.write(json);
    file.commit();
  }
  std::cout << json;
}

// The -o file is tried before the benchmark runs, so that a mistyped folder is not found out after a ten-minute
// hectare, its JSON then lost: its temporary is written empty and removed at once (a FIFO or a device is only asked
// whether it may be written: AtomicFile::try_writing), with the same "cannot write FILE: REASON" as at the end (a
// folder given for the file included). Nothing is left behind either way.
void check_output_writable(const std::string& output) {
  if (output.empty()) return;
  AtomicFile probe(output);
  probe.try_writing();
}  // the probe's temporary is removed here: it was never committed

std::string check_device(const std::string& text) {
  try {
    compute::DeviceChoice::parse(text);
    return std::string();
  } catch (const std::invalid_argument& e) {
    return std::string(e.what());
  }
}

// `bench light --device`: an OpenCL device for the OpenCL rows (opencl, opencl:N, or auto, which falls back to the
// reference where there is none), or none. "reference" is refused: the OpenCL rows would time the reference solvers
// a second time under OpenCL's names; none runs the reference solvers alone.
std::string check_light_device(const std::string& text) {
  if (text == "none") return std::string();
  try {
    if (compute::DeviceChoice::parse(text).kind != compute::DeviceChoice::Kind::reference) return std::string();
    return "device 'reference': the OpenCL rows need an OpenCL device (opencl, opencl:N or auto); none runs the "
           "reference solvers alone";
  } catch (const std::invalid_argument&) {
    return "device '" + text + "': expected opencl, opencl:N (N >= 0), auto or none";
  }
}

// Where `backend`'s device cannot hold the far field at the culled parameters p's cap, a usage error naming `flag`,
// which gave the cap (light/far_field_buffers.hpp): the same words as a scenario's refusal, under the flag instead of a
// key.
void refuse_flag_beyond_device(const LightParameters& p, const compute::ComputeBackend& backend,
                               const CLI::Option& flag) {
  const auto memory = backend.memory();
  if (!memory) return;
  if (auto reason = far_field_beyond_device(p, *memory, backend.name()))
    throw CLI::ValidationError(flag.get_name(), *reason);
}

// The OpenCL device opened before any canopy is lit, so that a missing one fails at once rather than after the
// reference solvers' minutes on a large canopy (exit 1, as `grow` fails on a missing device).
// A far-field cap that device cannot hold is named then too: the synthetic canopies' and a stand's given by
// --far-field-table-mb under that flag, a stand's own under its scenario's key.
void open_light_device(const LightBenchmarkOptions& options, const std::vector<LightBenchmarkStand>& stands,
                       const CLI::Option& table_flag) {
  const std::string& text = options.opencl_device;
  if (text == "none") return;
  const auto choice = compute::DeviceChoice::parse(text);
  if (!compute::opencl_backend_built && choice.kind == compute::DeviceChoice::Kind::opencl)
    throw std::runtime_error("device '" + text + "': this build of heliostand has no OpenCL backend; --device none "
                             "runs the reference solvers alone");
  const auto backend = compute::ComputeBackend::open(choice);
  // options.parameters are the culled solver's already (light_benchmark.hpp)
  if (!options.ball_counts.empty()) refuse_flag_beyond_device(options.parameters, backend, table_flag);
  for (const auto& stand : stands) {
    LightParameters culled = stand.parameters;  // the benchmark's culled solver's (light_benchmark.cpp)
    culled.exact = false;
    if (table_flag.count() > 0)
      refuse_flag_beyond_device(culled, backend, table_flag);
    else
      refuse_far_field_beyond_device(culled, backend, stand.name);
  }
}

// `heliostand bench stand SCENARIO`: the scenario grown as `grow --no-vtk` grows it, timed (run/stand_benchmark.hpp).
void add_bench_stand_command(CLI::App& bench) {
  auto options = std::make_shared<StandBenchmarkOptions>();
  auto output = std::make_shared<std::string>();
  auto* stand = bench.add_subcommand(
      "stand", "Grow a scenario without the VTK series and report seconds per stage, tree-years/s and peak memory");
  stand->add_option("scenario", options->scenario, "Scenario TOML file")->required();
  stand->add_option("--years", options->years, "Years to simulate (overrides run.years)")->check(whole_number_check());
  stand->add_option("--seed", options->seed, "Random seed (overrides run.seed)")->check(seed_check());
  stand->add_option("--device", options->device, "auto | reference | opencl | opencl:N (overrides run.device)")
      ->check(check_device);
  stand->add_option("--tables", options->tables_folder,
                    "Keep the run's tables (stand_table.csv, trees.csv, events.csv, run.json) in this folder "
                    "(default: a temporary folder, removed)")
      ->check(path_check("folder"));
  stand->add_flag("-f,--force", options->force, "Replace the contents of a non-empty --tables folder");
  stand->add_option("-o,--output", *output, "Also write the JSON to this file")->check(path_check("file"));
  stand->callback([options, output] {
    options->command_line = invoked_command_line();
    // The input first (as `grow`), then the -o file, then the run: each mistake is found before any growth.
    const Scenario scenario = stand_benchmark_scenario(*options);
    check_output_writable(*output);
    print_json(run_stand_benchmark(scenario, *options), *output);
  });
}

// The command-line light flags that were given replace the stand's own [light] values; the others leave them. The
// far-field cap replaces the scenario's before its stand is established, so that the stand's memory is estimated with
// it (the callback of `bench light`); the others after.
struct LightOverrides {
  CLI::Option* cutoff = nullptr;
  CLI::Option* far_field_cell = nullptr;
  CLI::Option* hand_over = nullptr;
  CLI::Option* periodic = nullptr;
  CLI::Option* bias_correction = nullptr;
  CLI::Option* far_field_table = nullptr;

  void apply(const LightParameters& given, LightParameters& stand) const {
    if (cutoff->count() > 0) stand.cutoff_m = given.cutoff_m;
    if (far_field_cell->count() > 0) stand.far_field_cell_m = given.far_field_cell_m;
    if (hand_over->count() > 0) stand.far_field_hand_over_cells = given.far_field_hand_over_cells;
    if (periodic->count() > 0) stand.periodic = given.periodic;
    if (bias_correction->count() > 0) stand.far_field_bias_correction = given.far_field_bias_correction;
  }
};

// A synthetic canopy far beyond the machine is refused before any canopy is made, with its estimate
// (light/light_benchmark.hpp), as a run's stand is (stand/memory_estimate.hpp): under --far-field-table-mb where the
// canopy would fit at the default cap, else under --balls. Nothing is refused when the usable memory cannot be read.
void refuse_canopies_beyond_this_machine(const std::vector<std::size_t>& ball_counts, const LightParameters& p,
                                         const CLI::Option& balls, const CLI::Option& table_flag) {
  const auto usable = usable_memory_bytes();
  if (!usable) return;
  LightParameters default_table = p;
  default_table.far_field_table_mb = LightParameters{}.far_field_table_mb;
  for (std::size_t ball_count : ball_counts) {
    const std::uint64_t needed = synthetic_canopy_memory_bytes(ball_count, p);
    if (needed <= *usable) continue;
    const std::string estimate = fmt::format("{} ({}, docs/performance.md \"Memory\")", gibibytes(needed),
                                             synthetic_canopy_memory_formula(p));
    if (synthetic_canopy_memory_bytes(ball_count, default_table) <= *usable)
      throw CLI::ValidationError(table_flag.get_name(),
                                 fmt::format("a far-field table of up to {} MB brings {} leaf balls to about {}, more "
                                             "than the {} this machine lets the benchmark use: lower it (the far "
                                             "field's cells grow coarser instead)",
                                             p.far_field_table_mb, ball_count, estimate, gibibytes(*usable)));
    throw CLI::ValidationError(balls.get_name(), fmt::format("{} leaf balls need about {}, more than the {} this "
                                                             "machine lets the benchmark use",
                                                             ball_count, estimate, gibibytes(*usable)));
  }
}

// A scenario whose cap --far-field-table-mb replaced, refused under that flag where the cap takes the stand beyond
// this machine's memory (stand/memory_estimate.hpp). A stand too large at any cap is left to established_canopy,
// which refuses it under the scenario's own key as `grow` would.
void refuse_flag_beyond_this_machine(const Scenario& scenario, const std::string& name, const CLI::Option& table_flag) {
  const auto usable = usable_memory_bytes();
  if (!usable) return;
  if (auto reason = far_field_table_beyond_memory(scenario, estimate_run_memory(scenario), *usable))
    throw CLI::ValidationError(table_flag.get_name(), name + ": " + *reason);
}

// `heliostand bench light [--balls N ...] [--stand SCENARIO ...]` (light/light_benchmark.hpp).
void add_bench_light_command(CLI::App& bench) {
  auto options = std::make_shared<LightBenchmarkOptions>();
  auto scenarios = std::make_shared<std::vector<std::string>>();
  auto output = std::make_shared<std::string>();
  auto overrides = std::make_shared<LightOverrides>();
  auto* light = bench.add_subcommand("light", "Light solvers side by side on synthetic conifer canopies and on real stands");
  auto* balls = light->add_option("--balls", options->ball_counts,
                                  "Synthetic stand sizes in leaf balls (repeatable; default 1000, 10000 and 100000 "
                                  "unless --stand is given)")
                    ->check(whole_number_check());
  light->add_option("--stand", *scenarios,
                    "A scenario whose stand is established as `grow` establishes it (year 0, no growth) and lit with "
                    "its own [light] parameters (repeatable; combines with --balls)");
  light->add_option("--seed", options->seed, "Seed of the synthetic canopies")
      ->check(seed_check())
      ->capture_default_str();
  light->add_option("--device", options->opencl_device,
                    "OpenCL device for the OpenCL rows: opencl, opencl:N, auto (the reference where there is none) or "
                    "none (the reference solvers alone)")
      ->check(check_light_device)
      ->capture_default_str();
  const char* overrides_stand = " (synthetic stands; for a --stand, only when given: else its scenario's value)";
  overrides->cutoff = light->add_option("--cutoff", options->parameters.cutoff_m,
                                        std::string("Near-field cut-off, m") + overrides_stand)
                          ->check(positive_amount_check(max_light_distance_m))
                          ->capture_default_str();
  overrides->far_field_cell = light->add_option("--far-field-cell", options->parameters.far_field_cell_m,
                                                std::string("Far-field voxel edge, m") + overrides_stand)
                                  ->check(positive_amount_check(max_light_distance_m))
                                  ->capture_default_str();
  overrides->hand_over =
      light->add_option("--far-field-hand-over", options->parameters.far_field_hand_over_cells,
                        std::string("Cell edges beyond the cut-off where the far field takes over (with the bias "
                                    "correction)") +
                            overrides_stand)
          ->check(amount_between_check(0.0, max_far_field_hand_over_cells))
          ->capture_default_str();
  overrides->far_field_table =
      light->add_option("--far-field-table-mb", options->parameters.far_field_table_mb,
                        std::string("Memory cap of the far-field table, MB; an OpenCL device holds it twice (beyond "
                                    "it the cells grow coarser)") +
                            overrides_stand)
          ->check(amount_between_check(1.0, limit::far_field_table_mb.max))
          ->capture_default_str();
  overrides->periodic = light->add_flag("--periodic", options->parameters.periodic,
                                        std::string("Treat the plot as a torus") + overrides_stand);
  overrides->bias_correction =
      light->add_flag("--far-field-bias-correction,!--no-far-field-bias-correction",
                      options->parameters.far_field_bias_correction,
                      std::string("Correct the far field's dark bias, or not (on by default, as in [light]: "
                                  "docs/light.md)") +
                          overrides_stand);
  light->add_option("--reference-exact-max", options->reference_exact_max,
                    "Largest stand solved whole by reference exact (above: subsample)")
      ->check(whole_number_check(0))
      ->capture_default_str();
  light->add_option("--reference-culled-max", options->reference_culled_max,
                    "Largest stand solved whole by reference culled (above: subsample)")
      ->check(whole_number_check(0))
      ->capture_default_str();
  light->add_option("--opencl-exact-max", options->opencl_exact_max,
                    "Largest stand solved whole by OpenCL exact (above: subsample)")
      ->check(whole_number_check(0))
      ->capture_default_str();
  light->add_option("--subsample", options->subsample, "Balls in the subsample (timing extrapolation and errors)")
      ->check(whole_number_check())
      ->capture_default_str();
  auto* evaluations = light->add_option("--evaluations", options->evaluations,
                    "Evaluations of the OpenCL culled + far-field solver, one after another with one solver (the "
                    "first is the row's, the later ones are listed after it: they reuse the buffers it keeps)")
      ->check(whole_number_check(1, 1000))
      ->capture_default_str();
  light->add_option("-o,--output", *output, "Also write the JSON to this file")->check(path_check("file"));
  light->callback([options, scenarios, output, overrides, balls, evaluations] {
    // Later evaluations are of the OpenCL solver: without it there is nothing to repeat, and a flag that silently
    // did nothing would leave a user reading one evaluation as several.
    if (options->opencl_device == "none" && options->evaluations > 1)
      throw CLI::ValidationError(evaluations->get_name(),
                                 "more than one evaluation needs the OpenCL solver; --device none runs only the "
                                 "reference solvers, once each");
    // stdout carries the JSON; the progress lines go to the default logger, which writes to stderr at the level
    // -q / -v chose (cli/app.cpp)
    if (!scenarios->empty() && balls->count() == 0) options->ball_counts.clear();  // only the stands asked for
    refuse_canopies_beyond_this_machine(options->ball_counts, options->parameters, *balls, *overrides->far_field_table);
    // Every stand first: a bad scenario stops the command before any solver runs or any JSON is written.
    std::vector<LightBenchmarkStand> stands;
    for (const auto& file : *scenarios) {
      Scenario scenario = load_scenario(file);
      if (overrides->far_field_table->count() > 0) {
        scenario.light.far_field_table_mb = options->parameters.far_field_table_mb;
        refuse_flag_beyond_this_machine(scenario, file, *overrides->far_field_table);
      }
      stands.push_back(established_canopy(scenario, file));
      overrides->apply(options->parameters, stands.back().parameters);
    }
    // After the input's own checks (a bad scenario is the error named first), before the solvers:
    open_light_device(*options, stands, *overrides->far_field_table);
    check_output_writable(*output);
    print_json(run_light_benchmark(*options, stands), *output);
  });
}

}  // namespace

void add_bench_command(CLI::App& app) {
  auto* bench = app.add_subcommand("bench", "Benchmarks (timings and accuracy, printed as JSON)");
  bench->require_subcommand(1);
  add_bench_stand_command(*bench);
  add_bench_light_command(*bench);
}

}  // namespace heliostand::cli
