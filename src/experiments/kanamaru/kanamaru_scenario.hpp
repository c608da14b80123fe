#pragma once
// A seed-000 experiment as a scenario file (stands/kanamaru-*/scenario.toml): which start (the simple
// dichotomy model, two trees side by side, a bud sphere, bud clusters, a bud cylinder) and the model's
// parameters, Table 1 by default. docs/model.md lists the keys.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "architecture/bud_starts.hpp"
#include "architecture/kanamaru_growth.hpp"

namespace heliostand {

struct KanamaruScenario {
  std::filesystem::path file;
  std::string kind = "dichotomy";  // dichotomy | two_trees | bud_sphere | bud_clusters | bud_cylinder
  KanamaruParameters parameters;
  std::uint64_t seed = 1;
  double root_length = 15.0;        // root branch length in branch lengths (Figs. 10-14)
  double tree_spacing = 6.0;        // two_trees: distance between the two roots
  int remove_left_after = -1;       // two_trees: the left tree is cut after this generation (Fig. 11: 25)
  int buds = 50;                    // bud starts (Fig. 5: 50)
  double bud_radius = 5.0;          // bud sphere radius, or each cluster's radius
  int latest_sprouting = 20;        // sprouting generation uniform in 1..this (Fig. 5: 20)
  int clusters = 3;                 // bud_clusters
  double cluster_spread = 8.0;      // bud_clusters: cluster centres uniform in a disc of this radius
  double cylinder_height = 12.0;    // bud_cylinder
  double cylinder_radius = 1.0;
  int output_interval = 10;         // generations between VTK/CSV snapshots (the last is always written)
};

// Throws InputError naming file, line and key for every bad or unknown key.
KanamaruScenario load_kanamaru_scenario(const std::filesystem::path& file);

std::vector<BudStart> starts_of(const KanamaruScenario& scenario);

struct KanamaruRunSummary {
  int generations = 0;
  int tips = 0;
  int living_branches = 0;
  double seconds = 0;
};

// Grows the scenario and writes to `out`: generations.csv (one row per generation), tips.csv (final living
// tips), crown_gen_NNNN.vtp (io/dichotomy_tree_vtk.hpp) and crown.pvd. `out` is taken as `grow` takes its folder
// (io/output_folder.hpp): created if missing, refused if it holds anything unless `force` and it holds an earlier
// heliostand output, whose contents are then replaced. Every file is written whole under a temporary name and
// renamed into place; one that cannot be written throws OutputFolderError naming it and the reason.
KanamaruRunSummary run_kanamaru(const KanamaruScenario& scenario, const std::filesystem::path& out, bool force);

}  // namespace heliostand
