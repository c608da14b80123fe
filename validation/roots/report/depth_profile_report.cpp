// Report (not a test): the simulated cumulative root fraction with depth of the default tap-rooted
// conifer, against the temperate-coniferous-forest profile of Jackson et al. (1996, Oecologia 108:389,
// Table 1): Y = 1 − β^d, β = 0.976, d in cm (Y = fraction of root biomass above depth d).
// Usage: heliostand_roots_depth_report [OUTPUT.md]   (stdout without an argument)
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include "io/output_folder.hpp"
#include "root_experiments.hpp"
#include "roots/reference_root_field_solver.hpp"
#include "roots/root_metrics.hpp"

using namespace heliostand::roots;
using namespace heliostand::roots::validation;

int main(int argc, char** argv) {
  constexpr double jackson_beta = 0.976;
  constexpr int seeds = 4;
  constexpr int years = 20;
  const std::vector<double> depths_cm = {5, 10, 20, 30, 40, 50, 75, 100, 150, 200, 300};
  std::vector<double> depths_m;
  for (double d : depths_cm) depths_m.push_back(d / 100.0);

  // Two soils: uniform moisture, and a moist topsoil over drier subsoil (1.0 to 30 cm, 0.6 to 80 cm, 0.3
  // below), which hydrotropism should answer by rooting shallower.
  struct Soil {
    std::vector<double> bottoms, values;
  };
  const std::vector<Soil> soils{{{}, {}}, {{0.3, 0.8, 4.0}, {1.0, 0.6, 0.3}}};
  std::vector<std::vector<double>> by_length(soils.size(), std::vector<double>(depths_m.size(), 0.0));
  std::vector<std::vector<double>> by_volume = by_length;
  double segments = 0.0, total_length = 0.0;
  ReferenceRootFieldSolver solver;
  for (std::size_t soil = 0; soil < soils.size(); ++soil)
    for (int seed = 1; seed <= seeds; ++seed) {
      RootExperiment experiment;
      experiment.soil = {{-6.0, -6.0, -4.0}, 0.25, {48, 48, 16}};
      experiment.moisture_layer_bottoms_m = soils[soil].bottoms;
      experiment.moisture_layer_values = soils[soil].values;
      experiment.years = years;
      experiment.seed = seed;
      const RootExperimentResult result = run_experiment(experiment, solver);
      const auto tree = result.trees[0].segments();
      const auto length = cumulative_fraction_above(tree, result.soil.surface_z(), depths_m, false);
      const auto volume = cumulative_fraction_above(tree, result.soil.surface_z(), depths_m, true);
      for (std::size_t d = 0; d < depths_m.size(); ++d) {
        by_length[soil][d] += length[d] / seeds;
        by_volume[soil][d] += volume[d] / seeds;
      }
      if (soil == 0) {
        segments += static_cast<double>(tree.size()) / seeds;
        total_length += result.trees[0].total_length_m() / seeds;
      }
    }

  std::ostringstream out;
  out << fmt::format(
      "# Rooting-depth profile: simulated tap-rooted conifer vs Jackson et al. (1996)\n\n"
      "Default parameters (`roots::tap_rooted_conifer()`), one tree grown {} years, mean of {} seeds "
      "(uniform soil: {:.0f} segments, {:.1f} m of root), yearly recharge. Cumulative fraction of root "
      "length (L) and root volume π r² L (V) above each depth. Uniform: moisture 1.0 everywhere. Layered: "
      "moisture 1.0 to 30 cm, 0.6 to 80 cm, 0.3 below. Written by `heliostand_roots_depth_report`.\n\n"
      "| depth (cm) | Jackson Y = 1 − 0.976^d | uniform, L | uniform, V | layered, L | layered, V |\n"
      "|---:|---:|---:|---:|---:|---:|\n",
      years, seeds, segments, total_length);
  for (std::size_t d = 0; d < depths_cm.size(); ++d)
    out << fmt::format("| {:.0f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} |\n", depths_cm[d],
                       1.0 - std::pow(jackson_beta, depths_cm[d]), by_length[0][d], by_volume[0][d], by_length[1][d],
                       by_volume[1][d]);
  out << fmt::format("\nJackson's profile puts 50 % of the roots above {:.0f} cm and 95 % above {:.0f} cm.\n",
                     std::log(0.5) / std::log(jackson_beta), std::log(0.05) / std::log(jackson_beta));

  if (argc > 1) {
    const std::filesystem::path path(argv[1]);
    std::error_code ignored;
    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), ignored);
    try {
      heliostand::write_whole_file(path, out.str(), path);  // checked at its close: a full disk is an error too
    } catch (const heliostand::OutputFolderError& e) {
      std::cerr << "error: " << e.what() << "\n";
      return 2;
    }
  } else {
    std::cout << out.str();
  }
  return 0;
}
