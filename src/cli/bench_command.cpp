#include "cli/bench_command.hpp"

#include <fstream>
#include <iostream>
#include <memory>
#include <stdexcept>

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "light/light_benchmark.hpp"

namespace heliostand::cli {

void add_bench_command(CLI::App& app) {
  auto* bench = app.add_subcommand("bench", "Benchmarks (timings and accuracy, printed as JSON)");
  bench->require_subcommand(1);
  auto options = std::make_shared<LightBenchmarkOptions>();
  auto output = std::make_shared<std::string>();
  auto* light = bench->add_subcommand("light", "Light solvers side by side on synthetic conifer canopies");
  light->add_option("--balls", options->ball_counts, "Stand sizes in leaf balls (repeatable)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  light->add_option("--seed", options->seed, "Seed of the synthetic canopies")->capture_default_str();
  light->add_option("--device", options->opencl_device, "OpenCL device for the OpenCL rows: opencl, opencl:N or none")
      ->capture_default_str();
  light->add_option("--cutoff", options->parameters.cutoff_m, "Near-field cut-off, m")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  light->add_option("--far-field-cell", options->parameters.far_field_cell_m, "Far-field voxel edge, m")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  light->add_flag("--periodic", options->parameters.periodic, "Treat the plot as a torus");
  light->add_option("--reference-exact-max", options->reference_exact_max,
                    "Largest stand solved whole by reference exact (above: subsample)")
      ->capture_default_str();
  light->add_option("--reference-culled-max", options->reference_culled_max,
                    "Largest stand solved whole by reference culled (above: subsample)")
      ->capture_default_str();
  light->add_option("--opencl-exact-max", options->opencl_exact_max,
                    "Largest stand solved whole by OpenCL exact (above: subsample)")
      ->capture_default_str();
  light->add_option("--subsample", options->subsample, "Balls in the subsample (timing extrapolation and errors)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  light->add_option("-o,--output", *output, "Also write the JSON to this file");
  light->callback([options, output] {
    // stdout carries the JSON: progress lines go to stderr (DESIGN.md: logs on stderr)
    if (!spdlog::get("heliostand-bench")) spdlog::set_default_logger(spdlog::stderr_color_mt("heliostand-bench"));
    const std::string json = run_light_benchmark(*options);
    std::cout << json;
    if (!output->empty()) {
      std::ofstream out(*output);
      if (!(out << json)) throw std::runtime_error("cannot write " + *output);
    }
  });
}

}  // namespace heliostand::cli
