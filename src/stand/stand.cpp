#include "stand/stand.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <limits>

#include <glm/geometric.hpp>

#include "core/parallel_for.hpp"
#include "geometry/planting_rows.hpp"
#include "records/stand_metrics.hpp"
#include "stand/light_response.hpp"
#include "stand/mortality.hpp"

namespace heliostand {

Stand::Stand(double plot_area_ha, int stand_age, std::vector<StandTree> trees,
             std::vector<ThinningEvent> thinning, CompetitionNeighbourhood competition)
    : plot_area_ha_(plot_area_ha),
      stand_age_(stand_age),
      trees_(std::move(trees)),
      thinning_(std::move(thinning)),
      last_fired_age_(thinning_.size()),
      competition_(competition) {}

void Stand::grow_year() {
  ++stand_age_;
  // Each crown grows from its own state and random stream: the trees are independent.
  parallel_for(trees_.size(), [&](std::size_t i) {
    if (trees_[i].alive()) trees_[i].conifer.grow_year();
  });
}

namespace {
template <typename Work>
auto timed(StageClock* clock, const char* stage, Work work) {
  return clock != nullptr ? clock->time(stage, work) : work();
}
}  // namespace

std::size_t Stand::illuminate(LightSolver& stand_solver, LightSolver& open_solver, double sky_scale,
                              StageClock* clock) {
  // Gather every living tree's leaf balls into one array (the solver sees the whole stand), remember
  // where each tree's run starts, solve once, and hand each tree its slice back.
  std::vector<LeafBall> balls;
  std::vector<std::size_t> first_ball(trees_.size() + 1, 0);
  // The open-grown reference is every tree alone (first_ball delimits each tree's balls). Where the stand's solver
  // can, it lights the trees alone in the same pass (LightSolver::solve_with_each_alone), all timed as "light";
  // otherwise the open-grown solve runs after it, on its own clock.
  std::vector<LightSample> open_grown;
  bool lit_alone = false;
  const std::vector<LightSample> samples = timed(clock, "light", [&] {
    std::vector<std::vector<LeafBall>> own(trees_.size());
    parallel_for(trees_.size(), [&](std::size_t i) {
      if (trees_[i].alive()) own[i] = trees_[i].conifer.leaf_balls();
    });
    for (std::size_t i = 0; i < trees_.size(); ++i) {
      first_ball[i] = balls.size();
      balls.insert(balls.end(), own[i].begin(), own[i].end());
      std::vector<LeafBall>().swap(own[i]);
    }
    first_ball[trees_.size()] = balls.size();
    if (auto both = stand_solver.solve_with_each_alone(balls, first_ball, open_solver)) {
      open_grown = std::move(both->alone);
      lit_alone = true;
      return std::move(both->stand);
    }
    return stand_solver.solve(balls);
  });
  if (!lit_alone)
    open_grown = timed(clock, "light (open grown)", [&] { return open_solver.solve_each_alone(balls, first_ball); });
  parallel_for(trees_.size(), [&](std::size_t i) {
    StandTree& tree = trees_[i];
    if (!tree.alive()) return;
    const std::span<const LightSample> open(open_grown.data() + first_ball[i], first_ball[i + 1] - first_ball[i]);
    const std::vector<int> foliage = tree.conifer.foliage_shoot_indices();
    std::vector<ConiferTree::FoliageLight> light(foliage.size());
    LightBudget budget;
    for (std::size_t k = 0; k < foliage.size(); ++k) {
      const LightSample& in_stand = samples[first_ball[i] + k];
      const double received = sky_scale * in_stand.light;
      light[k] = {in_stand.light, relative_light(in_stand.light, open[k].light, sky_scale), in_stand.vector};
      const Shoot& shoot = tree.conifer.shoots()[foliage[k]];
      const double foliage_amount = glm::length(shoot.tip - shoot.base);
      budget.absorbed += foliage_amount * received;
      budget.absorbed_open += foliage_amount * open[k].light;
    }
    tree.conifer.set_foliage_light(light);
    tree.light_budget = budget;
    tree.conifer.set_light_budget(budget.absorbed, budget.absorbed_open);
  });
  return balls.size();
}

TreeEvent Stand::end_of(StandTree& tree, TreeEventKind kind, std::string_view cause, const std::string& reason) {
  tree.status = kind == TreeEventKind::removed ? TreeStatus::removed : TreeStatus::dead;
  tree.status_changed_at_age = stand_age_;
  tree.status_reason = reason;
  return {.stand_age = stand_age_, .tree_id = tree.id, .label = tree.label, .species = tree.species, .kind = kind,
          .cause = std::string(cause), .reason = reason, .dbh_cm = tree.conifer.dbh_cm(),
          .height_m = tree.conifer.height_m(), .volume_m3 = tree.conifer.stem_volume_m3()};
}

TreeEvent Stand::remove(StandTree& tree, const std::string& reason) {
  return end_of(tree, TreeEventKind::removed, thinning_cause, reason);
}

TreeEvent Stand::kill(StandTree& tree, DeathCause cause) {
  const std::string code(cause_code(cause));
  return end_of(tree, TreeEventKind::died, code, code);
}

std::vector<TreeEvent> Stand::respond_to_light(std::uint64_t seed) {
  // Every crown responds to the light it was given, independently (its own random stream); deaths are then
  // recorded in tree order, so the events do not depend on the number of threads.
  std::vector<char> died(trees_.size(), 0);
  parallel_for(trees_.size(), [&](std::size_t i) {
    if (trees_[i].alive()) died[i] = heliostand::respond_to_light(trees_[i].conifer, seed).tree_died;
  });
  std::vector<TreeEvent> deaths;
  for (std::size_t i = 0; i < trees_.size(); ++i)
    if (died[i]) deaths.push_back(kill(trees_[i], DeathCause::light));
  if (!deaths.empty()) spdlog::info("age {}: {} trees died of light", stand_age_, deaths.size());
  return deaths;
}

std::vector<TreeEvent> Stand::apply_mortality(std::uint64_t seed) {
  std::vector<TreeEvent> deaths;
  for (StandTree& tree : trees_) {
    if (!tree.alive()) continue;
    if (const auto cause = draw_mortality(tree.conifer, seed))
      deaths.push_back(kill(tree, *cause));
  }
  const auto crowded = die_of_crowding();
  deaths.insert(deaths.end(), crowded.begin(), crowded.end());
  if (!deaths.empty()) spdlog::info("age {}: {} trees died of suppression or background mortality", stand_age_, deaths.size());
  return deaths;
}

// Self-thinning at maximum density (stand/mortality.hpp): the least-growing trees die until the stand is back
// under its species' density limit.
std::vector<TreeEvent> Stand::die_of_crowding() {
  std::vector<std::size_t> living;
  std::vector<CrowdingCandidate> candidates;
  for (std::size_t i = 0; i < trees_.size(); ++i) {
    if (!trees_[i].alive()) continue;
    const ConiferTree& tree = trees_[i].conifer;
    const SpeciesParameters& species = tree.species();
    living.push_back(i);
    candidates.push_back({tree.dbh_cm(), species.max_stand_density_index * species.self_thinning_limit,
                          tree.recent_radial_growth_mm(species.suppression_growth_years)});
  }
  std::vector<TreeEvent> deaths;
  for (std::size_t chosen : select_crowding_deaths(candidates, plot_area_ha_))
    deaths.push_back(kill(trees_[living[chosen]], DeathCause::suppression));
  return deaths;
}

std::vector<TreeEvent> Stand::thin() {
  std::vector<TreeEvent> removed;
  for (std::size_t k = 0; k < thinning_.size(); ++k) {
    const ThinningEvent& event = thinning_[k];
    // Conditions read the stand as the events before this one left it this year.
    const StandMeasures stand = event.when.condition ? measures() : StandMeasures{};
    const auto why = why_thinning_fires(event.when, stand_age_, last_fired_age_[k], stand);
    if (!why) continue;
    last_fired_age_[k] = stand_age_;
    auto events = apply(event, *why);
    removed.insert(removed.end(), events.begin(), events.end());
  }
  return removed;
}

std::size_t Stand::release_gone_crowns(const std::function<bool(const StandTree&)>& written_for_the_last_time) {
  std::size_t released = 0;
  for (StandTree& tree : trees_) {
    if (tree.alive() || tree.conifer.crown_released() || !written_for_the_last_time(tree)) continue;
    tree.conifer.release_crown();
    ++released;
  }
  return released;
}

StandMeasures Stand::measures() const {
  std::vector<TreeMeasurement> living;
  for (const auto& tree : trees_) {
    if (!tree.alive()) continue;
    TreeMeasurement measured;  // volume and species are not needed for basal area and top height
    measured.dbh_cm = tree.conifer.dbh_cm();
    measured.height_m = tree.conifer.height_m();
    living.push_back(measured);
  }
  const StandMetrics metrics = measure_stand(living, plot_area_ha_);
  return {metrics.basal_area_m2_per_ha, metrics.top_height_m};
}

std::vector<double> Stand::hegyi_indices() const {
  std::vector<std::size_t> living;
  std::vector<glm::dvec2> positions;
  std::vector<double> dbh;
  for (std::size_t i = 0; i < trees_.size(); ++i) {
    if (!trees_[i].alive()) continue;
    living.push_back(i);
    positions.emplace_back(trees_[i].conifer.stem_base());
    dbh.push_back(trees_[i].conifer.dbh_cm());
  }
  const Neighbourhood stems(positions, competition_.edges);
  const std::vector<double> of_living = heliostand::hegyi_indices(stems, dbh, competition_.radius_m);
  std::vector<double> indices(trees_.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t k = 0; k < living.size(); ++k) indices[living[k]] = of_living[k];
  return indices;
}

// Rows come from every planting position, the trees that have left included: the numbering stays the same from
// one row thinning to the next. The scenario check found rows in the survey's positions, which are these.
std::vector<int> Stand::planting_rows(const RowSettings& settings) const {
  std::vector<glm::dvec2> positions;
  for (const auto& tree : trees_) positions.emplace_back(tree.conifer.stem_base());
  const PlantingRowsFound found = find_planting_rows(positions, settings.azimuth_deg, settings.tolerance_m);
  if (found.rows) return found.rows->row_of;
  spdlog::warn("age {}: no planting rows: {}", stand_age_, found.problem);
  return std::vector<int>(trees_.size(), -1);
}

std::vector<ThinningCandidate> Stand::candidates_for(const ThinningEvent& event,
                                                     const std::vector<std::size_t>& living) const {
  std::vector<ThinningCandidate> candidates;
  for (std::size_t i : living) {
    const StandTree& tree = trees_[i];
    const glm::dvec3 base = tree.conifer.stem_base();
    candidates.push_back({tree.label, tree.conifer.dbh_cm(), event.protect_habitat_trees && tree.is_habitat_tree(),
                          tree.conifer.height_m(), base.x, base.y});
  }
  // Only the regimes that read them pay for the neighbourhood and the rows.
  if (event.rule.method == ThinningMethod::crop_tree) {
    const auto hegyi = hegyi_indices();
    for (std::size_t k = 0; k < living.size(); ++k) candidates[k].hegyi_index = hegyi[living[k]];
  }
  if (event.rule.method == ThinningMethod::rows) {
    const auto rows = planting_rows(event.rule.rows);
    for (std::size_t k = 0; k < living.size(); ++k) candidates[k].planting_row = rows[living[k]];
  }
  return candidates;
}

namespace {

void log_removals(int stand_age, const ThinningEvent& event, const std::string& why,
                  const std::vector<TreeEvent>& removed, long kept_habitat_trees, double plot_area_ha) {
  double basal_area = 0, volume = 0;
  for (const auto& tree : removed) {
    basal_area += basal_area_m2(tree.dbh_cm);
    volume += tree.volume_m3;
  }
  const std::string kept = kept_habitat_trees > 0 ? fmt::format(", kept {} habitat trees", kept_habitat_trees) : "";
  spdlog::info("age {}: {} ({}, {}) removed {} trees: {:.1f} stems/ha, basal area {:.2f} m²/ha, volume {:.1f} m³/ha{}",
               stand_age, event.reason, thinning_method_name(event.rule.method), why, removed.size(),
               static_cast<double>(removed.size()) / plot_area_ha, basal_area / plot_area_ha, volume / plot_area_ha,
               kept);
}

}  // namespace

std::vector<TreeEvent> Stand::apply(const ThinningEvent& event, const std::string& why) {
  std::vector<std::size_t> living;
  for (std::size_t i = 0; i < trees_.size(); ++i)
    if (trees_[i].alive()) living.push_back(i);
  const std::vector<ThinningCandidate> candidates = candidates_for(event, living);
  std::vector<TreeEvent> removed;
  for (std::size_t chosen : select_for_thinning(event.rule, candidates, ThinningPlot{plot_area_ha_, competition_.edges}))
    removed.push_back(remove(trees_[living[chosen]], event.reason));
  const auto kept = std::count_if(candidates.begin(), candidates.end(), [](const auto& c) { return c.is_protected; });
  log_removals(stand_age_, event, why, removed, kept, plot_area_ha_);
  return removed;
}

}  // namespace heliostand
