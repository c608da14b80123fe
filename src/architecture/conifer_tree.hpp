#pragma once
// One conifer grown by the seed-001 rules (Ohsaki et al.): a stem growing by the Chapman–Richards
// height curve, whorls of first-order branches, opposite pairs of lower-order branches, growth stop by
// order, dead branches that persist and then fall tip-first. docs/model.md "Seed 001" explains each rule.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "architecture/branch_axis.hpp"
#include "architecture/shoot.hpp"
#include "architecture/species.hpp"
#include "core/checkpoint_access.hpp"

namespace heliostand {

struct StemTaper;

// What calibration fits per tree (stand/calibration.hpp) on top of its species.
struct TreeCalibration {
  double site_asymptote_m = 28.0;   // eq. 1 A: fitted so the height at survey age equals the surveyed height
  double elongation_scale = 1.0;    // multiplies branch elongation: fitted to the surveyed crown radius
  double growth_stop_years_first_order = 18.0;  // eq. 12 base: fitted to the surveyed crown base
};

class ConiferTree {
 public:
  ConiferTree(const SpeciesParameters& species, const TreeCalibration& calibration,
              glm::dvec3 stem_base, std::uint64_t seed, int tree_id);

  // Advance one year: age + 1, stem and branch elongation, new whorl, growth stop, death, fall.
  void grow_year();
  void grow_to_age(int age);  // grow_year() until age() == age

  int age() const { return age_; }
  double height_m() const { return height_m_; }  // grown by the site curve's increment x the leader's light
  double dbh_cm() const { return dbh_cm_; }       // grown by basal-area increments; 0 while shorter than 1.3 m
  // Height of the lowest living first-order branch (height if none), never below the surveyed crown base: the
  // survey's value holds until the whorl below it dies (set_survey_state()).
  double crown_base_m() const;
  double crown_radius_m() const;    // projected crown radius of living foliage (definition in docs/model.md)
  double stem_volume_m3() const;    // stem volume: eq. 2's taper scaled to the tree's own DBH, integrated

  // Start the tree as surveyed (stand/establishment.cpp): its DBH and crown base are the record's. First-order
  // branches below the highest whorl at or under the recorded crown base die (they persist and fall, eq. 13).
  void set_survey_state(double dbh_cm, double crown_base_m);
  // In a stand, first-order branches die of light (a starved tip, LIGNUM's bud death) instead of after the
  // growth-stop years of eq. 12, which only shaped the crown up to the survey.
  void set_light_driven_crown(bool on) { light_driven_crown_ = on; }
  bool light_driven_crown() const { return light_driven_crown_; }
  // This year's light of every leaf ball (leaf_balls() order): the light in the stand and the relative light
  // (stand / the tree alone). Shoots without a ball take their bearer's. grow_year() reads them next year.
  struct FoliageLight {
    double light = 1.0;
    double relative_light = 1.0;
    glm::dvec3 vector{0.0, 0.0, 1.0};
  };
  void set_foliage_light(std::span<const FoliageLight> light);
  // The light of each leaf ball (leaf_balls() order), from its shoot.
  std::vector<FoliageLight> foliage_light() const;
  // The light the tree's foliage absorbed this year (Σ foliage amount × light, in the stand and with the tree
  // alone; stand/stand_tree.hpp LightBudget): next year's basal-area increment follows it. The first call fixes
  // the reference: the crown as established, alone, is the foliage its stem's basal area carries (pipe model).
  void set_light_budget(double absorbed, double absorbed_open);
  // This year's absorbed light over the pipe-model reference scaled to today's basal area (1 without a light field).
  double pipe_model_share() const;
  // The tree's DBH / eq. 2's DBH for its height and crown base (1 below 1.3 m): the stem is the taper scaled by it.
  double stem_scale() const;
  // The tree's calibrated site curve (eq. 1): the height a leader in full light reaches at `age`.
  double height_at(int age) const;
  // Radial increment at breast height of the last `years` years, mean in mm/year (suppression mortality).
  double recent_radial_growth_mm(int years) const;
  double last_dbh_increment_cm() const { return dbh_increments_cm_.empty() ? 0.0 : dbh_increments_cm_.back(); }

  const std::vector<Shoot>& shoots() const { return shoots_; }
  const std::vector<BranchAxis>& axes() const { return axes_; }
  std::vector<LeafBall> leaf_balls() const;  // one per living shoot tip that carries foliage
  std::vector<int> foliage_shoot_indices() const;  // the shoot of each leaf ball, in leaf_balls() order
  bool carries_foliage(const Shoot& shoot) const;
  std::size_t living_shoot_count() const;
  glm::dvec3 stem_base() const { return stem_base_; }
  int id() const { return tree_id_; }
  const SpeciesParameters& species() const { return species_; }
  const TreeCalibration& calibration() const { return calibration_; }

  // Hooks for the light response (docs/architecture.md, the simulated year, step 3), used after grow_year():
  std::vector<int> new_shoot_indices() const;  // the shoots that flushed this year
  // Turn a shoot to a new direction about its base, keeping its length; everything it carries moves with it.
  void bend_shoot(int shoot_index, glm::dvec3 direction);
  // Remove a shoot with everything it carries (the rest of its axis and all laterals on them).
  void remove_shoot(int shoot_index);
  // Seed 000's death rule on this year's shoots (stand/light_response.hpp): each listed branch shoot dies, and
  // with it its axis and every lateral the axis carries; they persist as dead wood and fall by eq. 13.
  // Stem shoots are ignored (the stem's fate is the tree's). Returns the number of axes killed.
  int kill_shaded_shoots(const std::vector<int>& shoot_indices);
  // Whether any living branch shoot still carries foliage.
  bool has_living_branch_foliage() const;
  // Years in a row the leader has been shaded out (stand/light_response.hpp keeps the count).
  int leader_shaded_years() const { return leader_shaded_years_; }
  void record_leader_light(bool shaded_out) { leader_shaded_years_ = shaded_out ? leader_shaded_years_ + 1 : 0; }

  // A tree that has left the stand, once nothing will read its crown again, gives the crown back: its shoots and
  // axes (most of a tree's memory) are dropped; age, height, DBH and stem base stay. Nothing may grow, light or
  // measure the crown afterwards (crown base, crown radius and stem volume read it).
  void release_crown();
  bool crown_released() const { return axes_.empty(); }  // a tree always has its stem axis until then

  // Crown–root coupling (seed 003's Branch_n, src/coupling/): bonus[n] is added to the flushing probability
  // (clamped to 0..1) of every lateral bud on a branch whose first-order axis leaves the trunk in path n
  // (45° sector of its azimuth, counter-clockwise from +x). A bud whose own probability is 0 stays off.
  void set_branching_bonus(const std::array<double, 8>& bonus) { branching_bonus_ = bonus; }
  const std::array<double, 8>& branching_bonus() const { return branching_bonus_; }

 private:
  friend struct checkpoint::Access;
  void grow_diameter(double open_grown_height_m);
  double elongation_factor(int shoot_index) const;
  double stem_scale(const StemTaper& taper) const;  // this tree's DBH over the taper's
  int add_shoot(int axis, int parent_shoot, glm::dvec3 base, glm::dvec3 tip);
  int add_axis(int order, int parent_axis, double initial_elongation_m, double azimuth_rad);
  void grow_stem(double height_growth_m);
  void grow_branches();
  void grow_axis(int axis_index);
  void sprout_laterals(int parent_axis_index, int bearing_shoot);
  void sprout_whorl(double height_growth_m);
  void kill_axis(int axis_index);
  void droop_first_order_branches();
  void drop_dead_branches();
  void flag_descendants(std::vector<char>& flags, std::size_t first) const;
  void remove_flagged(std::vector<char> removed);
  void fit_lists_to_size();
  void update_radii();
  double axis_length_m(const BranchAxis& axis) const;

  SpeciesParameters species_;
  TreeCalibration calibration_;
  glm::dvec3 stem_base_;
  std::uint64_t seed_;
  int tree_id_;
  int age_ = 0;
  int next_axis_id_ = 0;
  int leader_shaded_years_ = 0;
  double height_m_ = 0;
  double dbh_cm_ = 0;
  double crown_base_floor_m_ = 0;
  bool light_driven_crown_ = false;
  double absorbed_light_ = 0;              // this year's Σ foliage × light (m)
  double reference_absorbed_light_ = 0;    // the established crown alone (0: not set, taper-driven growth)
  double reference_dbh_cm_ = 0;            // the DBH when that reference was taken (pipe model)
  std::vector<double> dbh_increments_cm_;  // one per year grown (recent years at the back, at most 10)
  std::vector<Shoot> shoots_;
  std::vector<BranchAxis> axes_;  // axes_[0] is the stem
  std::array<double, 8> branching_bonus_{};  // crown–root coupling, by path
  double with_branching_bonus(double probability, int axis_index) const;
};

}  // namespace heliostand
