#pragma once
// A tree as the stand manager keeps it: its architecture, where it came from (the survey record),
// its status, and the light its leaf balls received this year.
#include <string>
#include <vector>

#include "architecture/conifer_tree.hpp"
#include "hollow/hollow_spec.hpp"
#include "io/tree_status.hpp"
#include "light/light_solver.hpp"

namespace heliostand {

struct StandTree {
  int id = 0;                 // 0-based index in the stand, stable for the whole run
  std::string label;          // the survey record's id
  std::string species;
  ConiferTree tree;
  TreeStatus status = TreeStatus::alive;
  int status_changed_at_age = -1;  // stand age of death or removal
  std::string status_reason;       // e.g. "thinning from below", "light"
  // Hollows (docs/hollows.md), seeds resolved: a tree carrying one is a habitat tree, protected from thinning
  // unless a thinning says otherwise.
  std::vector<hollow::HollowSpec> hollows;

  std::vector<LightSample> leaf_ball_light;  // one per leaf_balls() entry, from this year's light field
  double mean_light() const;                 // sky openness: mean light of its leaf balls (1 if none)

  bool alive() const { return status == TreeStatus::alive; }
  bool is_habitat_tree() const { return !hollows.empty(); }
};

}  // namespace heliostand
