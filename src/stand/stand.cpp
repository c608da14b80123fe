#include "stand/stand.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>

#include "stand/light_response.hpp"

namespace heliostand {

Stand::Stand(double plot_area_ha, int stand_age, std::vector<StandTree> trees,
             std::vector<ScheduledThinning> thinning)
    : plot_area_ha_(plot_area_ha),
      stand_age_(stand_age),
      trees_(std::move(trees)),
      thinning_(std::move(thinning)) {}

void Stand::grow_year() {
  ++stand_age_;
  for (auto& tree : trees_)
    if (tree.alive()) tree.tree.grow_year();
}

std::size_t Stand::illuminate(LightSolver& solver) {
  // Gather every living tree's leaf balls into one array (the solver sees the whole stand), remember
  // where each tree's run starts, solve once, and hand each tree its slice back.
  std::vector<LeafBall> balls;
  std::vector<std::size_t> first_ball(trees_.size() + 1, 0);
  for (std::size_t i = 0; i < trees_.size(); ++i) {
    first_ball[i] = balls.size();
    if (!trees_[i].alive()) continue;
    const auto own = trees_[i].tree.leaf_balls();
    balls.insert(balls.end(), own.begin(), own.end());
  }
  first_ball[trees_.size()] = balls.size();

  const std::vector<LightSample> samples = solver.solve(balls);
  for (std::size_t i = 0; i < trees_.size(); ++i)
    trees_[i].leaf_ball_light.assign(samples.begin() + static_cast<std::ptrdiff_t>(first_ball[i]),
                                     samples.begin() + static_cast<std::ptrdiff_t>(first_ball[i + 1]));
  return balls.size();
}

namespace {

// Shoots killed by the response stop carrying foliage (they are flagged, not renumbered): drop their samples so
// leaf_ball_light stays one per leaf_balls() entry for the outputs.
void keep_light_of_surviving_foliage(StandTree& tree, const std::vector<int>& foliage_before) {
  const std::vector<int> foliage_after = tree.tree.foliage_shoot_indices();
  std::vector<LightSample> kept;
  kept.reserve(foliage_after.size());
  for (std::size_t k = 0, j = 0; k < foliage_before.size() && j < foliage_after.size(); ++k)
    if (foliage_before[k] == foliage_after[j]) {
      kept.push_back(tree.leaf_ball_light[k]);
      ++j;
    }
  tree.leaf_ball_light = std::move(kept);
}

}  // namespace

std::vector<TreeEvent> Stand::respond_to_light(LightSolver& solver, std::uint64_t seed) {
  std::vector<TreeEvent> deaths;
  for (StandTree& tree : trees_) {
    if (!tree.alive()) continue;
    const std::vector<LightSample> open = open_grown_light(tree.tree, solver);
    const std::vector<int> foliage_before = tree.tree.foliage_shoot_indices();
    const LightResponseOutcome outcome = heliostand::respond_to_light(tree.tree, tree.leaf_ball_light, open, seed);
    keep_light_of_surviving_foliage(tree, foliage_before);
    if (!outcome.tree_died) continue;
    tree.status = TreeStatus::dead;
    tree.status_changed_at_age = stand_age_;
    tree.status_reason = "light";
    tree.leaf_ball_light.clear();
    deaths.push_back({stand_age_, tree.id, tree.label, TreeEventKind::died, "light", tree.tree.dbh_cm(),
                      tree.tree.height_m(), tree.tree.stem_volume_m3()});
  }
  if (!deaths.empty()) spdlog::info("age {}: {} trees died of light", stand_age_, deaths.size());
  return deaths;
}

std::vector<TreeEvent> Stand::thin() {
  std::vector<TreeEvent> removed;
  for (const auto& event : thinning_) {
    if (event.stand_age != stand_age_) continue;
    auto events = apply(event);
    removed.insert(removed.end(), events.begin(), events.end());
  }
  return removed;
}

std::vector<TreeEvent> Stand::apply(const ScheduledThinning& event) {
  std::vector<std::size_t> living;
  std::vector<ThinningCandidate> candidates;
  for (std::size_t i = 0; i < trees_.size(); ++i) {
    if (!trees_[i].alive()) continue;
    living.push_back(i);
    candidates.push_back({trees_[i].label, trees_[i].tree.dbh_cm(),
                          event.protect_habitat_trees && trees_[i].is_habitat_tree()});
  }
  std::vector<TreeEvent> removed;
  for (std::size_t chosen : select_for_thinning(event.rule, candidates, plot_area_ha_)) {
    StandTree& tree = trees_[living[chosen]];
    tree.status = TreeStatus::removed;
    tree.status_changed_at_age = stand_age_;
    tree.status_reason = event.reason;
    tree.leaf_ball_light.clear();
    removed.push_back({stand_age_, tree.id, tree.label, TreeEventKind::removed, event.reason,
                       tree.tree.dbh_cm(), tree.tree.height_m(), tree.tree.stem_volume_m3()});
  }
  const auto kept = std::count_if(candidates.begin(), candidates.end(), [](const auto& c) { return c.is_protected; });
  if (kept > 0)
    spdlog::info("age {}: {} removed {} trees, kept {} habitat trees", stand_age_, event.reason, removed.size(), kept);
  else
    spdlog::info("age {}: {} removed {} trees", stand_age_, event.reason, removed.size());
  return removed;
}

}  // namespace heliostand
