#pragma once
// The stand manager: every tree of the plantation, grown together one year at a time.
// One simulated year (DESIGN.md): grow → light → (respond) → thin → metrics; data flows one way.
#include <cstdint>
#include <string>
#include <vector>

#include "io/tree_event.hpp"
#include "light/light_solver.hpp"
#include "stand/stand_tree.hpp"
#include "stand/thinning.hpp"

namespace heliostand {

struct ScheduledThinning {
  int stand_age = 0;      // happens at the end of the year in which the stand reaches this age
  ThinningRule rule;
  std::string reason;     // label in events.csv, e.g. "first thinning"
  bool protect_habitat_trees = true;  // trees with hollows are kept
};

class Stand {
 public:
  Stand(double plot_area_ha, int stand_age, std::vector<StandTree> trees,
        std::vector<ScheduledThinning> thinning);

  int stand_age() const { return stand_age_; }
  double plot_area_ha() const { return plot_area_ha_; }
  const std::vector<StandTree>& trees() const { return trees_; }
  // Mutable access for per-tree hooks kept outside the stand (crown–root coupling, stand/root_zone.hpp).
  StandTree& tree_at(std::size_t index) { return trees_.at(index); }

  // Every living tree grows one year; the stand ages by one.
  void grow_year();
  // The light field of the whole stand: every living tree's leaf balls shade every other's.
  // Returns the number of leaf balls lit.
  std::size_t illuminate(LightSolver& solver);
  // Seed 000's response to this year's light (stand/light_response.hpp): new shoots bend toward their light
  // vector or die of shade; trees left without foliage die (cause "light"). Call after illuminate(); `solver`
  // also lights each tree alone (the open-grown reference). Returns the deaths.
  // `open_grown_solver` lights each tree alone (the reference its relative light is measured against).
  std::vector<TreeEvent> respond_to_light(LightSolver& open_grown_solver, std::uint64_t seed);
  // Thinnings scheduled for the current stand age. Returns the removals, in removal order.
  std::vector<TreeEvent> thin();

 private:
  std::vector<TreeEvent> apply(const ScheduledThinning& event);

  double plot_area_ha_;
  int stand_age_;
  std::vector<StandTree> trees_;
  std::vector<ScheduledThinning> thinning_;
};

}  // namespace heliostand
