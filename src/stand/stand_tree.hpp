#pragma once
// A tree as the stand manager keeps it: its architecture, where it came from (the survey record),
// its status, and the light it received this year (kept on its shoots, summed here into its light budget).
#include <algorithm>
#include <string>
#include <vector>

#include "architecture/conifer_tree.hpp"
#include "hollow/hollow_spec.hpp"
#include "light/light_solver.hpp"
#include "records/tree_status.hpp"

namespace heliostand {

// The light a tree absorbed this year (docs/model.md "Growth from light"): each leaf ball's light (0..1 of the
// open sky) times its foliage amount, summed over the tree's balls; the same sum with the tree standing alone
// under the reference sky; and their ratio, the tree's relative light. Foliage amount of a ball = the length of
// the shoot it sits on (m): the needles of a first-order annual shoot and the laterals lumped into its ball.
struct LightBudget {
  double absorbed = 0;       // Σ foliage · light in the stand, m
  double absorbed_open = 0;  // Σ foliage · light of the tree alone, m
  double relative() const { return absorbed_open > 0.0 ? std::min(1.0, absorbed / absorbed_open) : 0.0; }
};

// The members after `conifer` carry an initialiser, even an empty one, so that an aggregate initialisation that
// stops at `conifer` or skips members (`StandTree{.id = …, .conifer = …, .hollows = …}`) says "the rest as a new
// tree has it" without -Wmissing-field-initializers, which gcc raises for designated initialisers too.
struct StandTree {
  int id = 0;                 // 0-based index in the stand, stable for the whole run
  std::string label;          // the survey record's id
  std::string species;
  ConiferTree conifer;        // the growing tree: stem and crown, shoot by shoot (its roots are in the root zone)
  TreeStatus status = TreeStatus::alive;
  int status_changed_at_age = -1;  // stand age of death or removal
  std::string status_reason{};     // e.g. "thinning from below", "light", "suppression"
  // Hollows (docs/hollows.md), seeds resolved: a tree carrying one is a habitat tree, protected from thinning
  // unless a thinning says otherwise.
  std::vector<hollow::HollowSpec> hollows{};

  LightBudget light_budget{};  // this year's (Stand::illuminate); zero before the first light field

  // The light of each leaf ball (leaf_balls() order), read from its shoots.
  std::vector<LightSample> leaf_ball_light() const;
  double mean_light() const;  // sky openness: mean light of its leaf balls (1 if none)

  bool alive() const { return status == TreeStatus::alive; }
  bool is_habitat_tree() const { return !hollows.empty(); }
};

}  // namespace heliostand
