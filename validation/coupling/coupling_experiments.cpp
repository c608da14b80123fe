#include "coupling_experiments.hpp"

#include "coupling/crown_root_balance.hpp"
#include "light/make_light_solver.hpp"
#include "stand/root_zone.hpp"
#include "stand/stand.hpp"

namespace heliostand::coupling_validation {

bool is_right_path(int path) { return path == 6 || path == 7 || path == 0 || path == 1; }

namespace {

RootsSettings settings_for(const CoupledExperiment& e) {
  RootsSettings settings;
  settings.soil.spacing_m = 0.5;
  settings.soil.depth_m = 3.0;
  settings.soil.nutrient.value = e.nutrient;
  settings.coupling.enabled = e.coupled;
  if (e.prune_right_paths) settings.pruning.push_back({0, std::nullopt, true, {6, 7, 0, 1}, 0.0, 0.0, {}});
  if (e.prune_left_paths) settings.pruning.push_back({0, std::nullopt, true, {2, 3, 4, 5}, 0.0, 0.0, {}});
  return settings;
}

int new_roots_this_year(const roots::RootSystem& roots) {
  int started = 0;
  for (const roots::RootSegment& s : roots.segments())
    started += s.parent >= 0 && s.birth_year == roots.year() && s.axis_birth_year == s.birth_year;
  return started;
}

}  // namespace

CoupledResult run_coupled(const CoupledExperiment& e) {
  const PlotBounds plot{0.0, 0.0, 10.0, 10.0};
  std::vector<StandTree> trees;
  SpeciesParameters species;
  species.foliage_years = 3;  // a lighter crown (Todomatsu keeps 5): the O(balls²) light solve stays fast
  // A leaf ball on every shoot, as in seed 003's single-tree experiments: Branch_n acts on the laterals, and
  // only with their own balls does more or less lateral foliage show in LP_n and in the measured crown.
  species.foliage_max_order = 3;
  trees.push_back(StandTree{0, "1", "todomatsu", ConiferTree(species, TreeCalibration{}, {5.0, 5.0, 0.0}, e.seed, 0)});
  Stand stand(plot.area_ha(), 0, std::move(trees), {});

  LightParameters light;
  light.sky_bands = 8;   // a coarse sky: one lone tree needs no finer one
  light.sky_sectors = 16;
  light.sky_scale = e.sky_scale;
  light.cutoff_m = 1.0;  // near field within 1 m, far field (1 m voxels) beyond: a 12-year crown is ~3 m wide
  light.far_field_cell_m = 1.0;
  const auto reference = compute::ComputeBackend::reference();
  auto solver = make_light_solver(reference, light);

  RootZone zone(settings_for(e), plot, e.seed, e.sky_scale, reference);
  zone.establish(stand);
  stand.illuminate(*solver, *solver, e.sky_scale);
  zone.couple(stand);

  CoupledResult result;
  int ratios = 0;
  for (int year = 1; year <= e.years; ++year) {
    stand.grow_year();
    stand.illuminate(*solver, *solver, e.sky_scale);
    zone.grow_year(stand);
    result.root_branches += new_roots_this_year(*zone.roots_of(0));
    if (const PathBalance* b = zone.balance_of(0)) {
      double lp = 0.0, wp = 0.0;
      for (std::size_t n = 0; n < 8; ++n) lp += b->lp[n], wp += b->wp[n];
      if (wp > 0.0) {
        result.mean_lp_over_wp += lp / wp;
        ++ratios;
      }
    }
  }
  if (ratios > 0) result.mean_lp_over_wp /= ratios;

  const ConiferTree& tree = stand.trees()[0].conifer;
  result.root_length_m = zone.roots_of(0)->total_length_m();
  result.shoots = static_cast<double>(tree.living_shoot_count());
  for (int shoot : tree.foliage_shoot_indices()) {
    result.leaf_balls += 1;
    const int path = crown_path_of_shoot(tree, shoot);
    if (path < 0) continue;
    (is_right_path(path) ? result.foliage_right : result.foliage_left) += 1;
  }
  return result;
}

CoupledResult mean_over_seeds(CoupledExperiment experiment, int count) {
  CoupledResult mean;
  for (int s = 1; s <= count; ++s) {
    experiment.seed = static_cast<std::uint64_t>(s);
    const CoupledResult r = run_coupled(experiment);
    mean.root_branches += r.root_branches / count;
    mean.root_length_m += r.root_length_m / count;
    mean.shoots += r.shoots / count;
    mean.leaf_balls += r.leaf_balls / count;
    mean.foliage_right += r.foliage_right / count;
    mean.foliage_left += r.foliage_left / count;
    mean.mean_lp_over_wp += r.mean_lp_over_wp / count;
  }
  return mean;
}

}  // namespace heliostand::coupling_validation
