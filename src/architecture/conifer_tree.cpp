#include "architecture/conifer_tree.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "architecture/branch_angle.hpp"
#include "architecture/branch_diameter.hpp"
#include "architecture/elongation.hpp"
#include "architecture/growth_stop.hpp"
#include "architecture/height_curve.hpp"
#include "architecture/light_growth.hpp"
#include "architecture/lower_order_branching.hpp"
#include "architecture/stem_taper.hpp"
#include "architecture/whorl.hpp"
#include "geometry/angles.hpp"
#include "geometry/compass_sector.hpp"
#include "geometry/vertical.hpp"
#include "rng/random_stream.hpp"

namespace heliostand {

namespace {

// Random-stream tags: each (tree, year, organ kind, axis) draws from its own stream.
enum Organ : std::uint64_t { kWhorl = 1, kLateralPair = 2 };

// Unit vector at `angle` from the vertical, leaning towards `azimuth` (x east = 0, counter-clockwise).
glm::dvec3 direction_from(double angle_from_vertical, double azimuth) {
  return {std::sin(angle_from_vertical) * std::cos(azimuth), std::sin(angle_from_vertical) * std::sin(azimuth),
          std::cos(angle_from_vertical)};
}

double angle_from_vertical(glm::dvec3 v) {
  return std::acos(std::clamp(v.z / glm::length(v), -1.0, 1.0));
}

// A turn about the unit axis k by an angle (right-handed), its cosine and sine taken once: a droop or a bend turns
// every shoot it carries by the same angle, and a sine and cosine for each shoot's base and tip were a large part of
// an old tree's growth (docs/performance.md "Eq. 11 once a shoot").
struct Rotation {
  glm::dvec3 axis{0.0, 0.0, 1.0};
  double cosine = 1.0;
  double sine = 0.0;
};

Rotation rotation_about(glm::dvec3 k, double angle) { return {k, std::cos(angle), std::sin(angle)}; }

// Rodrigues' rotation of v.
glm::dvec3 rotate(glm::dvec3 v, const Rotation& r) {
  return v * r.cosine + glm::cross(r.axis, v) * r.sine + r.axis * glm::dot(r.axis, v) * (1.0 - r.cosine);
}

double shoot_length(const Shoot& shoot) { return glm::length(shoot.tip - shoot.base); }

// Tilt a direction up (positive angle) or down in its own vertical plane.
glm::dvec3 tilt_up(glm::dvec3 direction, double angle) {
  const glm::dvec3 towards_up = vertical_up - glm::dot(vertical_up, direction) * direction;
  const double norm = glm::length(towards_up);
  if (norm < 1e-9) return direction;  // vertical: no plane to tilt in
  return std::cos(angle) * direction + std::sin(angle) * (towards_up / norm);
}

}  // namespace

ConiferTree::ConiferTree(const SpeciesParameters& species, const TreeCalibration& calibration,
                         glm::dvec3 stem_base, std::uint64_t seed, int tree_id)
    : species_(species), calibration_(calibration), stem_base_(stem_base), seed_(seed), tree_id_(tree_id) {
  add_axis(0, -1, 0.0, 0.0);  // the stem
}

double ConiferTree::height_at(int age) const {
  return tree_height_m(species_, calibration_.site_asymptote_m, age);
}

int ConiferTree::add_axis(int order, int parent_axis, double initial_elongation_m, double azimuth_rad) {
  const int index = static_cast<int>(axes_.size());
  BranchAxis axis;
  axis.id = next_axis_id_++;
  axis.order = order;
  axis.parent_axis = parent_axis;
  axis.first_order_root = order == 0 ? -1 : order == 1 ? index : axes_[parent_axis].first_order_root;
  axis.year_formed = age_;
  axis.initial_elongation_m = initial_elongation_m;
  axis.azimuth_rad = azimuth_rad;
  axes_.push_back(axis);
  return index;
}

int ConiferTree::add_shoot(int axis, int parent_shoot, glm::dvec3 base, glm::dvec3 tip) {
  const int index = static_cast<int>(shoots_.size());
  Shoot shoot;
  shoot.base = base;
  shoot.tip = tip;
  shoot.parent = parent_shoot;
  shoot.axis = axis;
  shoot.order = axes_[axis].order;
  shoot.year_formed = age_;
  shoots_.push_back(shoot);
  axes_[axis].shoots.push_back(index);
  return index;
}

// One year, in the light the tree's foliage got last year (Shoot::light and relative_light, 1 for a tree grown
// alone): the leader makes the site curve's increment times its light response, every branch its seed-001
// elongation times its tip's response, and the stem its open-grown basal-area increment times the tree's light
// budget (docs/model.md "Growth from light").
void ConiferTree::grow_year() {
  ++age_;
  const double potential_height_growth = height_at(age_) - height_at(age_ - 1);
  const auto& stem = axes_[0].shoots;
  const double leader_light = stem.empty() ? 1.0 : shoots_[stem.back()].relative_light;
  const double height_growth = potential_height_growth * height_response(species_, leader_light);
  const std::size_t axes_before_this_year = axes_.size();
  grow_stem(height_growth);
  // Parents come before their laterals in the axis list, so a parent's death is known when its laterals
  // are visited; laterals that sprout during this loop are appended and not grown twice.
  for (std::size_t i = 1; i < axes_before_this_year; ++i) grow_axis(static_cast<int>(i));
  sprout_whorl(height_growth);
  droop_first_order_branches();
  drop_dead_branches();
  grow_diameter(height_m_ - height_growth + potential_height_growth);
  update_radii();
  fit_lists_to_size();
}

// The basal-area increment at breast height (docs/model.md "Growth from light"). Before any light field (a tree
// grown alone to its survey age) it is the open-grown increment of the taper, at the tree's own DBH. In a stand the
// potential is the basal-area increment of the taper's tree of this height along this year's potential height
// growth — what an open-grown stem of that height adds, whatever this stem's own history — times the response to
// the tree's light share (pipe_model_share). A slender suppressed stem thus catches up when released, as long
// as its crown carries the light.
void ConiferTree::grow_diameter(double open_grown_height_m) {
  const double before = dbh_cm_;
  const double previous_height = shoots_[axes_[0].shoots.back()].base.z - stem_base_.z;  // this year's leader base
  const double crown_base = crown_base_m();
  const double taper_before = StemTaper{previous_height, crown_base}.dbh_cm(species_);
  if (dbh_cm_ <= 0.0 || taper_before <= 0.0) {
    // Passing breast height: the stem starts with the taper's diameter at its height.
    dbh_cm_ = StemTaper{height_m_, crown_base}.dbh_cm(species_);
  } else {
    const double taper_after = StemTaper{open_grown_height_m, crown_base}.dbh_cm(species_);
    double increment = 0.0;  // in DBH² (cm²), proportional to basal area
    if (reference_absorbed_light_ <= 0.0) {
      // The tree's own DBH carried along the taper from one height to the next.
      const double open_dbh = dbh_cm_ * taper_after / taper_before;
      increment = std::max(0.0, open_dbh * open_dbh - dbh_cm_ * dbh_cm_);
    } else {
      const double potential = std::max(0.0, taper_after * taper_after - taper_before * taper_before);
      increment = potential * diameter_response(species_, pipe_model_share());
    }
    dbh_cm_ = std::sqrt(dbh_cm_ * dbh_cm_ + increment);
  }
  dbh_increments_cm_.push_back(dbh_cm_ - before);
  if (dbh_increments_cm_.size() > 10) dbh_increments_cm_.erase(dbh_increments_cm_.begin());
}

// The pipe model (Shinozaki et al. 1964): a stem's cross-section carries foliage in proportion to its area, so the
// light a stem of this basal area should absorb to grow as in the open is the light its established crown absorbed
// standing alone, scaled by basal area since then. The share is this year's absorbed light over that: below 1 for a
// shaded crown or for one that has shrunk against its stem, above 1 (capped) for a crown that outgrew its stem.
double ConiferTree::pipe_model_share() const {
  constexpr double max_share = 2.0;
  if (reference_absorbed_light_ <= 0.0 || reference_dbh_cm_ <= 0.0) return 1.0;
  const double basal_area_ratio = (dbh_cm_ * dbh_cm_) / (reference_dbh_cm_ * reference_dbh_cm_);
  return std::min(absorbed_light_ / (reference_absorbed_light_ * basal_area_ratio), max_share);
}

void ConiferTree::set_light_budget(double absorbed, double absorbed_open) {
  absorbed_light_ = absorbed;
  if (reference_absorbed_light_ > 0.0 || absorbed_open <= 0.0 || dbh_cm_ <= 0.0) return;
  reference_absorbed_light_ = absorbed_open;
  reference_dbh_cm_ = dbh_cm_;
}

double ConiferTree::recent_radial_growth_mm(int years) const {
  const int n = std::min<int>(years, static_cast<int>(dbh_increments_cm_.size()));
  if (n <= 0) return 0.0;
  double sum = 0.0;
  for (int k = 0; k < n; ++k) sum += dbh_increments_cm_[dbh_increments_cm_.size() - 1 - k];
  return 10.0 * sum / 2.0 / n;  // cm of diameter -> mm of radius
}

double ConiferTree::stem_scale() const { return stem_scale(StemTaper{height_m_, crown_base_m()}); }

double ConiferTree::stem_scale(const StemTaper& taper) const {
  const double taper_dbh = taper.dbh_cm(species_);
  return taper_dbh > 0.0 && dbh_cm_ > 0.0 ? dbh_cm_ / taper_dbh : 1.0;
}

// The light response of the shoot an axis grows from: its tip's relative light of last year.
double ConiferTree::elongation_factor(int shoot_index) const {
  return elongation_response(species_, shoots_[shoot_index].relative_light);
}

void ConiferTree::set_survey_state(double dbh_cm, double crown_base_m) {
  if (height_m_ > breast_height_m && dbh_cm > 0.0) dbh_cm_ = dbh_cm;
  // The highest living whorl at or below the record keeps the crown; everything living below it dies.
  double keep_from = -1.0;
  for (const BranchAxis& axis : axes_)
    if (axis.order == 1 && axis.alive && !axis.shoots.empty()) {
      const double insertion = shoots_[axis.shoots.front()].base.z - stem_base_.z;
      if (insertion <= crown_base_m + 1e-9) keep_from = std::max(keep_from, insertion);
    }
  if (keep_from >= 0.0)
    for (std::size_t i = 1; i < axes_.size(); ++i) {
      const BranchAxis& axis = axes_[i];
      if (axis.order != 1 || !axis.alive || axis.shoots.empty()) continue;
      if (shoots_[axis.shoots.front()].base.z - stem_base_.z < keep_from - 1e-6) {
        for (std::size_t j = i; j < axes_.size(); ++j)
          if (axes_[j].first_order_root == static_cast<int>(i) && axes_[j].alive) kill_axis(static_cast<int>(j));
      }
    }
  crown_base_floor_m_ = std::min(crown_base_m, height_m_);
  update_radii();
}

void ConiferTree::set_foliage_light(std::span<const FoliageLight> light) {
  const std::vector<int> foliage = foliage_shoot_indices();
  if (light.size() != foliage.size())
    throw std::invalid_argument("ConiferTree::set_foliage_light: " + std::to_string(light.size()) + " samples for " +
                                std::to_string(foliage.size()) + " leaf balls of tree " + std::to_string(tree_id_));
  std::vector<char> has_ball(shoots_.size(), 0);
  for (std::size_t k = 0; k < foliage.size(); ++k) {
    Shoot& shoot = shoots_[foliage[k]];
    shoot.light = light[k].light;
    shoot.relative_light = light[k].relative_light;
    shoot.light_vector = light[k].vector;
    has_ball[foliage[k]] = 1;
  }
  // Parents precede their laterals: one forward pass hands each bearer's light to the shoots without a ball.
  for (std::size_t i = 0; i < shoots_.size(); ++i)
    if (!has_ball[i] && shoots_[i].parent >= 0 && shoots_[i].order > 0) {
      const Shoot& bearer = shoots_[shoots_[i].parent];
      shoots_[i].light = bearer.light;
      shoots_[i].relative_light = bearer.relative_light;
      shoots_[i].light_vector = bearer.light_vector;
    }
}

std::vector<ConiferTree::FoliageLight> ConiferTree::foliage_light() const {
  std::vector<FoliageLight> light;
  for (const Shoot& shoot : shoots_)
    if (carries_foliage(shoot)) light.push_back({shoot.light, shoot.relative_light, shoot.light_vector});
  return light;
}

void ConiferTree::grow_to_age(int age) {
  while (age_ < age) grow_year();
}

void ConiferTree::grow_stem(double height_growth_m) {
  const auto& stem = axes_[0].shoots;
  const int leader = stem.empty() ? -1 : stem.back();
  const double relative_light = leader < 0 ? 1.0 : shoots_[leader].relative_light;
  const int shoot = add_shoot(0, leader, stem_base_ + vertical_up * height_m_,
                              stem_base_ + vertical_up * (height_m_ + height_growth_m));
  shoots_[shoot].relative_light = relative_light;  // until the new leader is lit
  height_m_ += height_growth_m;
}

void ConiferTree::grow_axis(int i) {
  if (!axes_[i].alive || axes_[i].shoots.empty()) return;
  const int parent = axes_[i].parent_axis;
  const int order = axes_[i].order;
  const int years_since_emergence = age_ - axes_[i].year_formed;
  const double stop_years = growth_stop_years(species_, calibration_.growth_stop_years_first_order, order);
  // A lateral dies with the branch that carries it; every branch dies when its growth stops (eq. 12) — in a
  // stand, first-order branches die of light instead: a tip whose light allows no elongation for
  // branch_starved_years_to_death years in a row dies (LIGNUM's bud death).
  const bool stops_by_age = !(light_driven_crown_ && order == 1) && !still_growing(years_since_emergence, stop_years);
  if ((parent > 0 && !axes_[parent].alive) || stops_by_age) {
    kill_axis(i);
    return;
  }
  const int last = axes_[i].shoots.back();
  const double response = elongation_factor(last);
  if (order == 1 && light_driven_crown_) {
    axes_[i].starved_years = response > 0.0 ? 0 : axes_[i].starved_years + 1;
    if (axes_[i].starved_years >= species_.branch_starved_years_to_death) {
      kill_axis(i);
      return;
    }
  }
  const double alpha = order == 1 ? species_.elongation_alpha : species_.lower_order_elongation_alpha;
  const double length =
      response * annual_elongation_m(axes_[i].initial_elongation_m, years_since_emergence + 1, alpha);
  const Shoot& previous = shoots_[last];
  // First order: this year's shoot follows eq. 4's angle, lifted by the anti-gravity offset (the droop step
  // then turns the whole branch so its chord sits exactly on eq. 4). Lower orders grow straight on.
  const glm::dvec3 direction =
      order == 1 ? direction_from(radians(first_order_branch_angle_deg(species_, years_since_emergence) -
                                          species_.first_order_upward_offset_deg),
                                  axes_[i].azimuth_rad)
                 : glm::normalize(previous.tip - previous.base);
  if (length <= 1e-4) return;  // no shoot below a tenth of a millimetre
  const Shoot bearer = previous;  // add_shoot() may move the shoot list
  const int shoot = add_shoot(i, last, bearer.tip, bearer.tip + direction * length);
  shoots_[shoot].light = bearer.light;  // until it is lit itself
  shoots_[shoot].relative_light = bearer.relative_light;
  shoots_[shoot].light_vector = bearer.light_vector;
  sprout_laterals(i, last);
}

// The opposite pair of order n+1 flushes where this year's shoot starts: at the tip of last year's shoot,
// from the buds it set. Its initial elongation is linear in that bearing shoot's elongation.
void ConiferTree::sprout_laterals(int parent_axis, int bearing_shoot) {
  const int order = axes_[parent_axis].order + 1;
  if (order > species_.max_order) return;
  if (!still_growing(0.0, growth_stop_years(species_, calibration_.growth_stop_years_first_order, order))) return;
  const Shoot bearing = shoots_[bearing_shoot];
  const double parent_elongation = shoot_length(bearing);
  const double probability =
      with_branching_bonus(lateral_occurrence_probability(species_, order, parent_elongation), parent_axis);
  const double initial = lower_order_initial_elongation_m(species_, parent_elongation);
  RandomStream random(seed_, {static_cast<std::uint64_t>(tree_id_), static_cast<std::uint64_t>(age_), kLateralPair,
                              static_cast<std::uint64_t>(axes_[parent_axis].id)});
  const glm::dvec3 along = glm::normalize(bearing.tip - bearing.base);
  glm::dvec3 side = glm::cross(along, vertical_up);
  side = glm::length(side) < 1e-9 ? glm::dvec3{1.0, 0.0, 0.0} : glm::normalize(side);
  const double spread = radians(species_.second_order_branch_angle_deg);
  for (double sign : {1.0, -1.0}) {
    const bool flushes = random.chance(probability);  // both draws always taken: streams stay aligned
    const double jitter = radians(species_.second_order_jitter_deg) * random.symmetric();
    if (!flushes || initial <= 0.0) continue;
    const glm::dvec3 direction = tilt_up(std::cos(spread) * along + std::sin(spread) * sign * side, jitter);
    const int axis = add_axis(order, parent_axis, initial, 0.0);
    add_shoot(axis, bearing_shoot, bearing.tip, bearing.tip + glm::normalize(direction) * initial);
  }
}

// Crown–root coupling: the path of a lateral is the sector of its first-order branch's azimuth on the trunk.
double ConiferTree::with_branching_bonus(double probability, int axis_index) const {
  const int first_order = axes_[axis_index].first_order_root;
  if (probability <= 0.0 || first_order < 0) return probability;
  const int path = compass_sector(axes_[first_order].azimuth_rad);
  return std::clamp(probability + branching_bonus_[path], 0.0, 1.0);
}

// This year's whorl flushes at the tip of last year's leader; its branches' tips start on the crown cone (eq. 9).
void ConiferTree::sprout_whorl(double height_growth) {
  const auto& stem = axes_[0].shoots;
  if (stem.size() < 2 || !still_growing(0.0, calibration_.growth_stop_years_first_order)) return;
  const int node_shoot = stem[stem.size() - 2];
  if (shoots_[node_shoot].year_formed != age_ - 1) return;
  const double initial =
      calibration_.elongation_scale * first_order_initial_elongation_m(species_, height_growth, age_);
  if (initial <= 0.0) return;
  RandomStream random(seed_, {static_cast<std::uint64_t>(tree_id_), static_cast<std::uint64_t>(age_), kWhorl});
  const int count = draw_whorl_size(species_, random);
  const glm::dvec3 node = shoots_[node_shoot].tip;
  const double lifted = radians(species_.initial_branch_angle_deg - species_.first_order_upward_offset_deg);
  for (double azimuth : whorl_azimuths(count, species_.whorl_azimuth_jitter, random)) {
    const int axis = add_axis(1, 0, initial, azimuth);
    const int shoot = add_shoot(axis, node_shoot, node, node + direction_from(lifted, azimuth) * initial);
    shoots_[shoot].light = shoots_[node_shoot].light;
    shoots_[shoot].relative_light = shoots_[node_shoot].relative_light;
  }
}

void ConiferTree::kill_axis(int i) {
  BranchAxis& axis = axes_[i];
  axis.alive = false;
  axis.year_stopped = age_;
  axis.length_at_death_m = axis_length_m(axis);
  for (int s : axis.shoots) shoots_[s].alive = false;
}

double ConiferTree::axis_length_m(const BranchAxis& axis) const {
  double total = 0.0;
  for (int s : axis.shoots) total += shoot_length(shoots_[s]);
  return total;
}

// Eqs. 4-6: every living first-order branch is turned about its insertion on the stem, in its own vertical
// plane, so that its chord (insertion → tip) makes exactly the eq.-4 angle with the stem axis. Everything it
// carries turns with it. The anti-gravity lift of each new shoot then shows as an upturned tip.
void ConiferTree::droop_first_order_branches() {
  std::vector<double> turn(axes_.size(), 0.0);
  std::vector<glm::dvec3> pivot(axes_.size());
  std::vector<Rotation> rotation(axes_.size());
  for (std::size_t i = 1; i < axes_.size(); ++i) {
    const BranchAxis& axis = axes_[i];
    if (axis.order != 1 || !axis.alive || axis.shoots.empty()) continue;
    pivot[i] = shoots_[axis.shoots.front()].base;
    const glm::dvec3 chord = shoots_[axis.shoots.back()].tip - pivot[i];
    const double horizontal = std::hypot(chord.x, chord.y);
    const double azimuth = horizontal > 1e-12 ? std::atan2(chord.y, chord.x) : axis.azimuth_rad;
    const glm::dvec3 hinge{-std::sin(azimuth), std::cos(azimuth), 0.0};  // turning about it by +θ lowers the branch
    const double target =
        std::clamp(radians(first_order_branch_angle_deg(species_, age_ - axis.year_formed)), 0.0, pi);
    turn[i] = target - angle_from_vertical(chord);
    rotation[i] = rotation_about(hinge, turn[i]);
  }
  for (Shoot& shoot : shoots_) {
    const int root = axes_[shoot.axis].first_order_root;
    if (root < 0 || turn[root] == 0.0) continue;
    shoot.base = pivot[root] + rotate(shoot.base - pivot[root], rotation[root]);
    shoot.tip = pivot[root] + rotate(shoot.tip - pivot[root], rotation[root]);
  }
}

// Eq. 13: a dead branch loses (years since stop / attached years) of its length, tip first. A shoot falls
// once it lies wholly in the lost tip fraction, so the last stub falls when the fraction reaches 1.
void ConiferTree::drop_dead_branches() {
  std::vector<char> fallen(shoots_.size(), 0);
  bool any = false;
  for (std::size_t i = 1; i < axes_.size(); ++i) {
    const BranchAxis& axis = axes_[i];
    if (axis.alive) continue;
    const double lost = dead_branch_loss_fraction(species_, age_ - axis.year_stopped);
    if (lost <= 0.0) continue;
    const double kept_length = (1.0 - lost) * axis.length_at_death_m;
    double distance_from_base = 0.0;
    for (int s : axis.shoots) {
      if (distance_from_base >= kept_length - 1e-12) {
        fallen[s] = 1;  // everything distal hangs on this shoot and falls with it
        any = true;
        break;
      }
      distance_from_base += shoot_length(shoots_[s]);
    }
  }
  if (any) remove_flagged(std::move(fallen));
}

// flags[k] is shoot first + k's flag (the tail of the shoot list from `first`); every descendant of a flagged shoot
// gets flagged. A shoot's parent always precedes it in the list, so one forward pass reaches every descendant.
void ConiferTree::flag_descendants(std::vector<char>& flags, std::size_t first) const {
  for (std::size_t i = first + 1; i < shoots_.size(); ++i) {
    const int parent = shoots_[i].parent;
    if (parent >= static_cast<int>(first) && flags[parent - first]) flags[i - first] = 1;
  }
}

// Removes the flagged shoots and everything they carry, then renumbers shoots and axes.
void ConiferTree::remove_flagged(std::vector<char> removed) {
  flag_descendants(removed, 0);

  std::vector<int> new_shoot_index(shoots_.size(), -1);
  std::vector<Shoot> kept;
  kept.reserve(static_cast<std::size_t>(std::count(removed.begin(), removed.end(), 0)));
  for (std::size_t i = 0; i < shoots_.size(); ++i) {
    if (removed[i]) continue;
    new_shoot_index[i] = static_cast<int>(kept.size());
    kept.push_back(shoots_[i]);
  }
  for (Shoot& shoot : kept)
    if (shoot.parent >= 0) shoot.parent = new_shoot_index[shoot.parent];
  shoots_ = std::move(kept);

  for (BranchAxis& axis : axes_) axis.shoots.clear();
  for (std::size_t i = 0; i < shoots_.size(); ++i) axes_[shoots_[i].axis].shoots.push_back(static_cast<int>(i));

  // Axes left without shoots are gone (the stem stays). Parents precede laterals here too.
  std::vector<int> new_axis_index(axes_.size(), -1);
  std::vector<BranchAxis> kept_axes;
  for (std::size_t i = 0; i < axes_.size(); ++i) {
    if (i != 0 && axes_[i].shoots.empty()) continue;
    new_axis_index[i] = static_cast<int>(kept_axes.size());
    kept_axes.push_back(std::move(axes_[i]));
  }
  for (BranchAxis& axis : kept_axes) {
    if (axis.parent_axis >= 0) axis.parent_axis = new_axis_index[axis.parent_axis];
    if (axis.first_order_root >= 0) axis.first_order_root = new_axis_index[axis.first_order_root];
  }
  axes_ = std::move(kept_axes);
  for (Shoot& shoot : shoots_) shoot.axis = new_axis_index[shoot.axis];
  fit_lists_to_size();
}

// A year's new shoots may have doubled the lists' capacity: up to half of a big crown's memory would hold nothing.
void ConiferTree::fit_lists_to_size() {
  shoots_.shrink_to_fit();
  axes_.shrink_to_fit();
}

// Stem radii by eq. 2 for the current height and crown base; living branch radii by eq. 11 from the length to
// the branch tip. Dead branches keep the radii they had when they died.
void ConiferTree::update_radii() {
  const StemTaper taper{height_m(), crown_base_m()};
  const double scale = stem_scale(taper);
  for (int s : axes_[0].shoots) {
    Shoot& shoot = shoots_[s];
    shoot.base_radius_m = 0.005 * scale * taper.diameter_cm(species_, shoot.base.z - stem_base_.z);
    shoot.tip_radius_m = 0.005 * scale * taper.diameter_cm(species_, shoot.tip.z - stem_base_.z);
  }
  for (std::size_t i = 1; i < axes_.size(); ++i) {
    if (!axes_[i].alive) continue;
    // From the branch tip down: a shoot's tip lies at the same length from the branch tip as the base of the shoot
    // before it in this loop, so eq. 11 (a power, most of this function's cost) is taken once a shoot and carried.
    double from_tip = 0.0;
    double diameter_cm = branch_diameter_cm(species_, from_tip);
    for (auto s = axes_[i].shoots.rbegin(); s != axes_[i].shoots.rend(); ++s) {
      Shoot& shoot = shoots_[*s];
      shoot.tip_radius_m = 0.005 * diameter_cm;
      from_tip += shoot_length(shoot);
      diameter_cm = branch_diameter_cm(species_, from_tip);
      shoot.base_radius_m = 0.005 * diameter_cm;
    }
  }
}

double ConiferTree::crown_base_m() const {
  double lowest = height_m();
  for (const BranchAxis& axis : axes_)
    if (axis.order == 1 && axis.alive && !axis.shoots.empty())
      lowest = std::min(lowest, shoots_[axis.shoots.front()].base.z - stem_base_.z);
  return std::min(std::max(lowest, crown_base_floor_m_), height_m());
}

double ConiferTree::stem_volume_m3() const {
  const StemTaper taper{height_m(), crown_base_m()};
  const double scale = stem_scale(taper);
  return scale * scale * taper.volume_m3(species_);
}

bool ConiferTree::carries_foliage(const Shoot& shoot) const {
  return shoot.alive && shoot.order <= species_.foliage_max_order &&
         age_ - shoot.year_formed < species_.foliage_years;
}

std::vector<LeafBall> ConiferTree::leaf_balls() const {
  std::vector<LeafBall> balls;
  for (const Shoot& shoot : shoots_) {
    if (!carries_foliage(shoot)) continue;
    const double radius = std::clamp(species_.leaf_ball_radius_ratio * shoot_length(shoot),
                                     species_.leaf_ball_min_radius_m, species_.leaf_ball_max_radius_m);
    balls.push_back({shoot.tip, radius});
  }
  return balls;
}

std::vector<int> ConiferTree::foliage_shoot_indices() const {
  std::vector<int> indices;
  for (std::size_t i = 0; i < shoots_.size(); ++i)
    if (carries_foliage(shoots_[i])) indices.push_back(static_cast<int>(i));
  return indices;
}

// Mean over the 8 compass sectors (45° each, around the stem) of the farthest horizontal reach of living foliage:
// leaf-ball centre distance from the stem axis plus the ball radius. An empty sector counts 0.
double ConiferTree::crown_radius_m() const {
  std::array<double, compass_sector_count> reach{};
  for (const LeafBall& ball : leaf_balls()) {
    const glm::dvec3 offset = ball.centre - stem_base_;
    const double distance = std::hypot(offset.x, offset.y);
    const int sector = compass_sector_of(offset);
    reach[sector] = std::max(reach[sector], distance + ball.radius);
  }
  double sum = 0.0;
  for (double r : reach) sum += r;
  return sum / compass_sector_count;
}

std::size_t ConiferTree::living_shoot_count() const {
  return static_cast<std::size_t>(
      std::count_if(shoots_.begin(), shoots_.end(), [](const Shoot& s) { return s.alive; }));
}

std::vector<int> ConiferTree::new_shoot_indices() const {
  std::vector<int> indices;
  for (std::size_t i = 0; i < shoots_.size(); ++i)
    if (shoots_[i].year_formed == age_) indices.push_back(static_cast<int>(i));
  return indices;
}

void ConiferTree::bend_shoot(int shoot_index, glm::dvec3 direction) {
  if (shoot_index < 0 || shoot_index >= static_cast<int>(shoots_.size()))
    throw std::out_of_range("ConiferTree::bend_shoot: no shoot " + std::to_string(shoot_index));
  const Shoot& bent = shoots_[shoot_index];
  const glm::dvec3 from = glm::normalize(bent.tip - bent.base);
  const glm::dvec3 to = glm::normalize(direction);
  const glm::dvec3 axis = glm::cross(from, to);
  const double sine = glm::length(axis);
  const double angle = std::atan2(sine, glm::dot(from, to));
  if (angle == 0.0) return;
  // Antiparallel directions have no unique hinge: any axis perpendicular to `from` will do.
  glm::dvec3 hinge = sine > 1e-12 ? axis / sine : glm::cross(from, glm::dvec3{1.0, 0.0, 0.0});
  if (glm::length(hinge) < 1e-9) hinge = glm::cross(from, glm::dvec3{0.0, 1.0, 0.0});
  hinge = glm::normalize(hinge);
  const glm::dvec3 pivot = bent.base;
  const Rotation turn = rotation_about(hinge, angle);
  // The bent shoot's descendants all lie after it: only that tail is looked at. The light response bends every
  // new shoot, and new shoots are the last in the list, so a bend costs the year's new shoots, not the whole
  // crown (which made the light response a fifth of the example's time).
  const std::size_t first = static_cast<std::size_t>(shoot_index);
  std::vector<char> moves(shoots_.size() - first, 0);
  moves[0] = 1;
  flag_descendants(moves, first);
  for (std::size_t i = first; i < shoots_.size(); ++i) {
    if (!moves[i - first]) continue;
    if (i != first) shoots_[i].base = pivot + rotate(shoots_[i].base - pivot, turn);
    shoots_[i].tip = pivot + rotate(shoots_[i].tip - pivot, turn);
  }
}

void ConiferTree::release_crown() {
  std::vector<Shoot>().swap(shoots_);
  std::vector<BranchAxis>().swap(axes_);
}

void ConiferTree::remove_shoot(int shoot_index) {
  if (shoot_index < 0 || shoot_index >= static_cast<int>(shoots_.size()))
    throw std::out_of_range("ConiferTree::remove_shoot: no shoot " + std::to_string(shoot_index));
  std::vector<char> removed(shoots_.size(), 0);
  removed[shoot_index] = 1;
  remove_flagged(std::move(removed));
}

int ConiferTree::kill_shaded_shoots(const std::vector<int>& shoot_indices) {
  std::vector<char> dying(axes_.size(), 0);
  for (int s : shoot_indices) {
    if (s < 0 || s >= static_cast<int>(shoots_.size()))
      throw std::out_of_range("ConiferTree::kill_shaded_shoots: no shoot " + std::to_string(s));
    if (shoots_[s].axis > 0) dying[shoots_[s].axis] = 1;
  }
  // Parents precede their laterals in the axis list: one forward pass carries death down every lateral.
  int killed = 0;
  for (std::size_t i = 1; i < axes_.size(); ++i) {
    if (!dying[i] && !(axes_[i].parent_axis > 0 && dying[axes_[i].parent_axis])) continue;
    dying[i] = 1;
    if (!axes_[i].alive) continue;
    kill_axis(static_cast<int>(i));
    ++killed;
  }
  return killed;
}

bool ConiferTree::has_living_branch_foliage() const {
  return std::any_of(shoots_.begin(), shoots_.end(),
                     [&](const Shoot& shoot) { return shoot.order > 0 && carries_foliage(shoot); });
}

}  // namespace heliostand
