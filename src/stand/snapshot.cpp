#include "stand/snapshot.hpp"

namespace heliostand {

TreeSnapshot snapshot_of(const StandTree& stand_tree) {
  const ConiferTree& tree = stand_tree.tree;
  TreeSnapshot snapshot;
  snapshot.id = stand_tree.id;
  snapshot.label = stand_tree.label;
  snapshot.position = tree.stem_base();
  snapshot.status = stand_tree.status;
  snapshot.age_years = tree.age();
  snapshot.height_m = tree.height_m();
  snapshot.dbh_cm = tree.dbh_cm();
  snapshot.crown_base_m = tree.crown_base_m();
  snapshot.crown_radius_m = tree.crown_radius_m();
  snapshot.volume_m3 = tree.stem_volume_m3();
  snapshot.mean_light = stand_tree.mean_light();
  snapshot.shoots = tree.shoots();
  if (stand_tree.alive()) {
    snapshot.leaf_balls = tree.leaf_balls();
    for (const auto& sample : stand_tree.leaf_ball_light) snapshot.leaf_ball_light.push_back(sample.light);
  }
  return snapshot;
}

StandSnapshot SnapshotTracker::take(const Stand& stand, int year_index) {
  const auto& trees = stand.trees();
  written_as_gone_.resize(trees.size(), false);
  StandSnapshot snapshot;
  snapshot.stand_age = stand.stand_age();
  snapshot.year_index = year_index;
  for (std::size_t i = 0; i < trees.size(); ++i) {
    if (!trees[i].alive()) {
      if (written_as_gone_[i]) continue;
      written_as_gone_[i] = true;
    }
    snapshot.trees.push_back(snapshot_of(trees[i]));
  }
  return snapshot;
}

}  // namespace heliostand
