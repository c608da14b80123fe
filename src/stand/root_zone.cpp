#include "stand/root_zone.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <spdlog/spdlog.h>

#include "core/parallel_for.hpp"
#include "roots/make_root_field_solver.hpp"
#include "roots/root_growth.hpp"
#include "roots/soil_file.hpp"
#include "scenario/scenario.hpp"

namespace heliostand {
namespace {

void fill_field(roots::SoilGrid& soil, roots::SoilField field, const SoilFieldSetting& setting) {
  switch (setting.kind) {
    case SoilFieldSetting::Kind::uniform: soil.fill_uniform(field, setting.value); break;
    case SoilFieldSetting::Kind::gradient: soil.fill_gradient(field, setting.axis, setting.at_min, setting.at_max); break;
    case SoilFieldSetting::Kind::layers: soil.fill_layers(field, setting.bottoms_m, setting.values); break;
  }
}

}  // namespace

roots::SoilGrid make_soil(const SoilSettings& settings, const PlotBounds& plot) {
  roots::SoilGridGeometry geometry;
  geometry.spacing_m = settings.spacing_m;
  geometry.origin = {plot.x_min, plot.y_min, -settings.depth_m};
  auto cells = [&](double extent) { return std::max(1, static_cast<int>(std::ceil(extent / settings.spacing_m - 1e-9))); };
  geometry.cells = {cells(plot.width_m()), cells(plot.depth_m()), cells(settings.depth_m)};
  roots::SoilGrid soil(geometry, 1.0, 1.0);
  fill_field(soil, roots::SoilField::moisture, settings.moisture);
  fill_field(soil, roots::SoilField::nutrient, settings.nutrient);
  if (settings.file) roots::read_soil_csv(*settings.file, soil);
  return soil;
}

RootZone::RootZone(RootsSettings settings, const PlotBounds& plot, std::uint64_t seed, double sky_scale,
                   const compute::ComputeBackend& backend)
    : settings_(std::move(settings)),
      seed_(seed),
      sky_scale_(sky_scale),
      soil_(make_soil(settings_.soil, plot)),
      solver_(roots::make_root_field_solver(backend)) {}

RootZone::~RootZone() = default;
RootZone::RootZone(RootZone&&) noexcept = default;

void RootZone::establish(const Stand& stand) {
  const auto& trees = stand.trees();
  roots_.assign(trees.size(), std::nullopt);
  balance_.assign(trees.size(), std::nullopt);
  int first_year = stand.stand_age();
  for (const StandTree& tree : trees) {
    if (!tree.alive()) continue;
    const int planted = stand.stand_age() - tree.conifer.age();
    const glm::dvec3 base = tree.conifer.stem_base();
    roots_[static_cast<std::size_t>(tree.id)].emplace(tree.id, glm::dvec3{base.x, base.y, soil_.surface_z()},
                                                      settings_.parameters_of(tree.species), planted);
    first_year = std::min(first_year, planted);
  }
  // Spin-up: the crowns were fitted one by one (establishment.cpp); the roots grow together from the
  // oldest tree's planting year, each tree joining in its own planting year, uncoupled (Root_n = 0).
  for (int year = first_year + 1; year <= stand.stand_age(); ++year) {
    std::vector<roots::RootSystem*> growing;
    for (auto& root : roots_)
      if (root && root->year() < year) growing.push_back(&*root);
    grow_roots_of(growing, year);
  }
}

void RootZone::grow_roots_of(const std::vector<roots::RootSystem*>& trees, int year) {
  if (!trees.empty()) roots::grow_roots(trees, soil_, *solver_, year, seed_);
  soil_.recharge(settings_.soil.recharge);
}

void RootZone::drop_gone_trees(const Stand& stand) {
  for (const StandTree& tree : stand.trees()) {
    const auto id = static_cast<std::size_t>(tree.id);
    if (!tree.alive() && id < roots_.size()) {
      roots_[id].reset();  // thinned or dead: its roots stop growing and leave the contact field
      balance_[id].reset();
    }
  }
}

void RootZone::couple(Stand& stand) {
  drop_gone_trees(stand);
  // Each tree's balance reads only its own crown and roots and the soil as it stands (no tree takes up water here):
  // the trees in parallel, the same answer on any number of threads.
  parallel_for(stand.trees().size(), [&](std::size_t i) {
    StandTree& tree = stand.tree_at(i);
    if (!tree.alive() || i >= roots_.size() || !roots_[i]) return;
    if (!settings_.coupling.enabled) {
      balance_[i] = PathBalance{};
      return;
    }
    const PathValues light = light_by_path(tree.conifer, tree.leaf_ball_light(), sky_scale_);
    const PathValues uptake = roots_[i]->available_uptake_by_path(soil_);
    balance_[i] = balance_paths(light, uptake, settings_.coupling);
    roots_[i]->set_branching_bonus(balance_[i]->root);
    tree.conifer.set_branching_bonus(balance_[i]->branch);
  });
}

void RootZone::prune(const Stand& stand) {
  for (const RootPruningEvent& event : settings_.pruning) {
    if (!event.every_year && event.stand_age != stand.stand_age()) continue;
    std::vector<int> sectors = event.sectors;
    if (sectors.empty()) sectors.push_back(roots::no_sector);
    for (const StandTree& tree : stand.trees()) {
      auto& root = roots_[static_cast<std::size_t>(tree.id)];
      if (!root) continue;
      if (!event.tree_labels.empty() &&
          std::find(event.tree_labels.begin(), event.tree_labels.end(), tree.label) == event.tree_labels.end())
        continue;
      for (int sector : sectors) root->prune({sector, event.min_depth_m, event.min_distance_m});
    }
  }
}

void RootZone::grow_year(Stand& stand) {
  drop_gone_trees(stand);
  prune(stand);
  couple(stand);
  std::vector<roots::RootSystem*> growing;
  for (auto& root : roots_)
    if (root) growing.push_back(&*root);
  grow_roots_of(growing, stand.stand_age());
}

const roots::RootSystem* RootZone::roots_of(int tree_id) const {
  const auto id = static_cast<std::size_t>(tree_id);
  return id < roots_.size() && roots_[id] ? &*roots_[id] : nullptr;
}

const PathBalance* RootZone::balance_of(int tree_id) const {
  const auto id = static_cast<std::size_t>(tree_id);
  return id < balance_.size() && balance_[id] ? &*balance_[id] : nullptr;
}

TreeRootSummary RootZone::summary_of(int tree_id) const {
  TreeRootSummary summary;
  const roots::RootSystem* root = roots_of(tree_id);
  if (!root) return summary;
  summary.length_m = root->total_length_m();
  for (const roots::RootSegment& segment : root->segments())
    if (segment.alive) summary.max_depth_m = std::max(summary.max_depth_m, soil_.surface_z() - segment.end.z);
  for (double w : root->available_uptake_by_path(soil_)) summary.uptake += w;
  return summary;
}

std::vector<const roots::RootSystem*> RootZone::living_roots() const {
  std::vector<const roots::RootSystem*> living;
  for (const auto& root : roots_)
    if (root) living.push_back(&*root);
  return living;
}

void RootZone::annotate(StandSnapshot& snapshot) const {
  for (TreeSnapshot& tree : snapshot.trees) {
    if (!roots_of(tree.id)) continue;  // gone trees keep NaN (empty cells)
    const TreeRootSummary summary = summary_of(tree.id);
    tree.root_length_m = summary.length_m;
    tree.root_max_depth_m = summary.max_depth_m;
    tree.root_uptake = summary.uptake;
  }
}

}  // namespace heliostand

namespace heliostand {

std::optional<RootZone> make_root_zone(const Scenario& scenario, const compute::ComputeBackend& backend) {
  if (!scenario.roots.enabled) return std::nullopt;
  std::optional<RootZone> zone;
  zone.emplace(scenario.roots, scenario.stand.plot, scenario.run.seed, scenario.light.sky_scale, backend);
  return zone;
}

std::optional<RootZone> establish_root_zone(const Scenario& scenario, const Stand& stand,
                                            const compute::ComputeBackend& backend) {
  auto zone = make_root_zone(scenario, backend);
  if (zone) zone->establish(stand);
  return zone;
}

}  // namespace heliostand
