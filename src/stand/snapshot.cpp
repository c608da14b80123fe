#include "stand/snapshot.hpp"

#include "core/parallel_for.hpp"
#include "stand/trunk_mesh.hpp"

namespace heliostand {

TreeSnapshot snapshot_of(const StandTree& stand_tree) {
  const ConiferTree& tree = stand_tree.conifer;
  TreeSnapshot snapshot;
  snapshot.id = stand_tree.id;
  snapshot.label = stand_tree.label;
  snapshot.species = stand_tree.species;
  snapshot.position = tree.stem_base();
  snapshot.status = stand_tree.status;
  snapshot.age_years = tree.age();
  snapshot.height_m = tree.height_m();
  snapshot.dbh_cm = tree.dbh_cm();
  snapshot.crown_base_m = tree.crown_base_m();
  snapshot.crown_radius_m = tree.crown_radius_m();
  snapshot.volume_m3 = tree.stem_volume_m3();
  snapshot.mean_light = stand_tree.mean_light();
  snapshot.light_budget = stand_tree.light_budget.absorbed;
  snapshot.relative_light = stand_tree.light_budget.relative();
  snapshot.dbh_increment_cm = tree.last_dbh_increment_cm();
  snapshot.status_reason = stand_tree.status_reason;
  snapshot.gone_at_age = stand_tree.alive() ? -1 : stand_tree.status_changed_at_age;
  snapshot.shoots = tree.shoots();
  snapshot.hollow_count = static_cast<int>(stand_tree.hollows.size());
  if (stand_tree.alive()) {
    snapshot.leaf_balls = tree.leaf_balls();
    for (const auto& sample : tree.foliage_light()) {
      snapshot.leaf_ball_light.push_back(sample.light);
      snapshot.leaf_ball_relative_light.push_back(sample.relative_light);
    }
    snapshot.leaf_ball_shoot = tree.foliage_shoot_indices();
  } else {
    snapshot.crown_when_gone = tree.leaf_balls();  // kept until its one gone year is written (StandYear)
  }
  return snapshot;
}

StandInventory take_inventory(const Stand& stand, int year_index) {
  StandInventory inventory{stand.stand_age(), year_index, {}};
  for (const StandTree& tree : stand.trees())
    if (tree.alive())
      inventory.living.push_back(
          {tree.conifer.dbh_cm(), tree.conifer.height_m(), tree.conifer.stem_volume_m3(), tree.species});
  return inventory;
}

StandSnapshot SnapshotTracker::take(const Stand& stand, int year_index) {
  const auto& trees = stand.trees();
  written_as_gone_.resize(trees.size(), false);
  StandSnapshot snapshot;
  snapshot.stand_age = stand.stand_age();
  snapshot.year_index = year_index;
  std::vector<const StandTree*> standing;  // per snapshot tree: the tree whose trunk to mesh, or null
  const std::vector<double> hegyi = stand.hegyi_indices();
  for (std::size_t i = 0; i < trees.size(); ++i) {
    if (!trees[i].alive()) {
      if (written_as_gone_[i]) continue;
      written_as_gone_[i] = true;
    }
    snapshot.trees.push_back(snapshot_of(trees[i]));
    snapshot.trees.back().hegyi_index = hegyi[i];
    standing.push_back(mesh_trunks_ && trees[i].status != TreeStatus::removed ? &trees[i] : nullptr);
  }
  // A felled tree leaves no stem; a dead one stands as a snag. Stems are meshed on all cores.
  parallel_for(standing.size(), [&](std::size_t k) {
    if (standing[k]) snapshot.trees[k].trunk = trunk_mesh_of(*standing[k]);
  });
  return snapshot;
}

}  // namespace heliostand
