#pragma once
// Everything one output year writes, decoupled from the simulation classes: the stand manager fills a
// StandSnapshot from its trees, the writers (VTK blocks, CSV tables) read only this.
//
// Extending: a later feature (roots, soil grid, trunk or hollow meshes) adds its data here — a field on
// TreeSnapshot for per-tree geometry, a field on StandSnapshot for stand-wide grids — and registers a
// block builder (io/vtk_stand_blocks.hpp) that turns it into one named block of the yearly multiblock.
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "architecture/shoot.hpp"
#include "hollow/hollow_mesh.hpp"
#include "records/tree_status.hpp"

namespace heliostand {

struct TreeSnapshot {
  int id = 0;
  std::string label;                // survey id
  std::string species;              // its [species.NAME] in the scenario
  glm::dvec3 position{0.0};         // m, stem base in stand coordinates
  TreeStatus status = TreeStatus::alive;
  double age_years = 0;
  double height_m = 0;
  double dbh_cm = 0;
  double crown_base_m = 0;
  double crown_radius_m = 0;
  double volume_m3 = 0;             // stem volume
  double mean_light = 0;            // mean light of the tree's leaf balls (0..1 of the open sky); NaN if unknown
  // The tree's light budget this year (docs/model.md "Growth from light"): Σ foliage amount × light over its
  // leaf balls (m of shoot), and its relative light (that sum / the same sum with the tree alone, 0..1).
  double light_budget = std::numeric_limits<double>::quiet_NaN();
  double relative_light = std::numeric_limits<double>::quiet_NaN();
  double dbh_increment_cm = 0;      // this year's DBH increment
  std::string status_reason;        // cause of death or thinning reason; empty while alive
  int gone_at_age = -1;             // stand age of its death or removal; -1 while alive
  // Roots (stand/root_zone.hpp, filled by RootZone::annotate); NaN when roots are off or the tree is gone.
  double root_length_m = std::numeric_limits<double>::quiet_NaN();
  double root_max_depth_m = std::numeric_limits<double>::quiet_NaN();
  double root_uptake = std::numeric_limits<double>::quiet_NaN();  // available uptake Σ W_j·moisture·nutrient
  // Hegyi's competition index among the living trees (stand/hegyi_index.hpp), 1/m; NaN when the tree is gone.
  double hegyi_index = std::numeric_limits<double>::quiet_NaN();

  // Geometry. `shoots` is a view into the tree's own shoot list (copying millions of shoots per output
  // year would cost more than writing them): it must stay valid while the snapshot is being written.
  std::span<const Shoot> shoots;
  std::vector<LeafBall> leaf_balls;
  std::vector<double> leaf_ball_light;  // one per leaf ball (same order), light 0..1 of the open sky; may be empty
  // One per leaf ball (same order): its light in the stand / its light with its tree alone, 0..1, the value the
  // shoot rules read (death threshold, elongation response); may be empty.
  std::vector<double> leaf_ball_relative_light;
  std::vector<int> leaf_ball_shoot;     // one per leaf ball (same order): its shoot's index in `shoots`; may be empty
  // A tree gone (dead or removed) since the previous output year is written once more, with the crown it had
  // when it went, so the year's VTK shows the stand before the thinning too (a Threshold on status shows it
  // after). `leaf_balls` stays empty for it: trees.csv counts the living foliage.
  std::vector<LeafBall> crown_when_gone;

  // Hollows (docs/hollows.md): how many the tree carries (> 0: a habitat tree), and its stem as a surface in
  // the tree frame (stem base at the origin), hollows included. Null when trunks are not meshed (a removed
  // tree, a tree without a stem) — the trunk block then has nothing for it.
  int hollow_count = 0;
  std::shared_ptr<const hollow::HollowMesh> trunk;
};

struct StandSnapshot {
  int stand_age = 0;     // years; the time value of this output year in ParaView and the tables
  int year_index = 0;    // 0 for the first simulated year of the run
  std::vector<TreeSnapshot> trees;
};

}  // namespace heliostand
