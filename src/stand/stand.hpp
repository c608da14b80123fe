#pragma once
// The stand manager: every tree of the plantation, grown together one year at a time. The steps of a simulated
// year are methods here; stand/stand_year.hpp owns their order (grow → light → respond → soil → mortality →
// thinning → metrics → write).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/checkpoint_access.hpp"
#include "light/light_solver.hpp"
#include "records/tree_event.hpp"
#include "stand/hegyi_index.hpp"
#include "stand/mortality.hpp"
#include "stand/stage_clock.hpp"
#include "stand/stand_tree.hpp"
#include "stand/thinning.hpp"
#include "stand/thinning_trigger.hpp"

namespace heliostand {

// The competitors a tree counts (stand/hegyi_index.hpp): within a radius, across the plot's edges as they are.
struct CompetitionNeighbourhood {
  double radius_m = default_competition_radius_m;
  StandEdges edges;
};

class Stand {
 public:
  // `thinning` in the order the events of one year are applied (the scenario's).
  Stand(double plot_area_ha, int stand_age, std::vector<StandTree> trees,
        std::vector<ThinningEvent> thinning, CompetitionNeighbourhood competition = {});

  int stand_age() const { return stand_age_; }
  double plot_area_ha() const { return plot_area_ha_; }
  const std::vector<StandTree>& trees() const { return trees_; }
  // Mutable access for per-tree hooks kept outside the stand (crown–root coupling, stand/root_zone.hpp).
  StandTree& tree_at(std::size_t index) { return trees_.at(index); }

  // Step 1. Every living tree grows one year in last year's light; the stand ages by one.
  void grow_year();
  // Step 2. The light field of the whole stand (every living tree's leaf balls shade every other's), and each
  // tree's crown alone under the reference sky (`open_solver`; the open-grown reference). Every leaf ball's
  // light, relative light (sky_scale × stand / open, at most 1) and light vector go onto its shoot, and each
  // tree's light budget is summed. Returns the number of leaf balls lit in the stand. With a clock, the stand's
  // solve (gathering the balls included) is timed as stage "light" and the open-grown one as "light (open grown)";
  // where the stand's solver lights the trees alone in the same pass (LightSolver::solve_with_each_alone), both are
  // in "light".
  std::size_t illuminate(LightSolver& stand_solver, LightSolver& open_solver, double sky_scale = 1.0,
                         StageClock* clock = nullptr);
  // Step 3. Seed 000's response to this year's light (stand/light_response.hpp): new shoots bend toward their
  // light vector or die of shade; trees left without foliage die (cause "light"). Returns the deaths.
  std::vector<TreeEvent> respond_to_light(std::uint64_t seed);
  // Step 5. Suppression (growth-based, then crowding above the density limit) and background mortality
  // (stand/mortality.hpp). Returns the deaths.
  std::vector<TreeEvent> apply_mortality(std::uint64_t seed);
  // Step 6. The thinnings whose trigger fires this year (stand/thinning_trigger.hpp), in order, each seeing the
  // stand the one before left. Returns the removals, in removal order.
  std::vector<TreeEvent> thin();

  // Step 9. Trees that have left the stand (removed or dead) give back their crowns (ConiferTree::release_crown) once
  // `written_for_the_last_time` says no output will read them again. Returns how many were let go.
  std::size_t release_gone_crowns(const std::function<bool(const StandTree&)>& written_for_the_last_time);

  // Hegyi's competition index of every tree (trees() order) among the living; NaN for trees not alive.
  std::vector<double> hegyi_indices() const;
  const CompetitionNeighbourhood& competition() const { return competition_; }

 private:
  friend struct checkpoint::Access;
  StandMeasures measures() const;
  std::vector<TreeEvent> apply(const ThinningEvent& event, const std::string& why);
  std::vector<ThinningCandidate> candidates_for(const ThinningEvent& event, const std::vector<std::size_t>& living) const;
  std::vector<int> planting_rows(const RowSettings& settings) const;
  std::vector<TreeEvent> die_of_crowding();
  // The tree leaves the living stand: removed by a thinning (cause thinning_cause, `reason` the scenario's) or
  // dead (cause and reason its death cause's code).
  TreeEvent remove(StandTree& tree, const std::string& reason);
  TreeEvent kill(StandTree& tree, DeathCause cause);
  TreeEvent end_of(StandTree& tree, TreeEventKind kind, std::string_view cause, const std::string& reason);

  double plot_area_ha_;
  int stand_age_;
  std::vector<StandTree> trees_;
  std::vector<ThinningEvent> thinning_;
  std::vector<std::optional<int>> last_fired_age_;  // per scheduled thinning
  CompetitionNeighbourhood competition_;
};

}  // namespace heliostand
