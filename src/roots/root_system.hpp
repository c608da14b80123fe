#pragma once
// The root system of one tree (seed 003): annual segments of the four root types, grown at their apices
// by the branching rules and the tropism direction rule, kept inside the soil, dying after their
// lifespan, pruned by path, and measured per path for the crown–root coupling (LP_n / WP_n).
//
// One year, driven for all trees of a stand by grow_roots() (root_growth.hpp):
//   1. buds()        — every growing apex proposes its continuation and new roots, and older woody
//                       segments may sprout fine roots (each segment draws from its own random stream)
//   2. the root-contact field is solved for all buds of all trees at once (RootFieldSolver)
//   3. add_segment() — one segment per bud, in the composed direction V
//   4. finish_year() — axes past their growth years stop; segments past their lifespan die (with what
//                       they carry); the segment list is compacted
//   5. take_up()     — young segments deplete soil moisture and nutrients near their tips
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "core/checkpoint_access.hpp"
#include "rng/random_stream.hpp"
#include "roots/root_parameters.hpp"
#include "roots/root_segment.hpp"
#include "roots/soil_grid.hpp"

namespace heliostand::roots {

// A new root apex about to form its first (or next) segment this year.
struct RootBud {
  int from_segment = -1;            // the apex segment it grows from (index in the tree's list)
  RootType type = RootType::main;
  bool continuation = false;        // extends the parent's axis; otherwise starts a new root
  int ordinal = 0;                  // 0 for the continuation, 1.. for new roots of the same apex
  glm::dvec3 inherited{0.0, 0.0, -1.0};      // Vn
  glm::dvec3 horizontal_fallback{1.0, 0.0, 0.0};  // Vd for a vertical Vn
};

// Pruning rule: remove every non-main segment of the path whose end is at least `min_depth_m` deep and
// at least `min_distance_m` (horizontally) from the root collar, and everything those segments carry.
struct RootPruning {
  int sector = no_sector;       // 0..7; no_sector = every path
  double min_depth_m = 0.0;
  double min_distance_m = 0.0;
};

// Random-stream organ tags (RandomStream(seed, {tree_id, year, organ, ...})).
inline constexpr std::uint64_t organ_root_bud = 0x726f6f74'62756400ULL;    // "root bud"
inline constexpr std::uint64_t organ_root_probe = 0x726f6f74'70726f62ULL;  // "root prob"

class RootSystem {
 public:
  // A seedling: one main-root segment straight down from the root collar (at the soil surface),
  // formed in `planting_year`. Throws std::invalid_argument for invalid parameters.
  RootSystem(int tree_id, const glm::dvec3& collar, RootParameters parameters, int planting_year);

  int tree_id() const { return tree_id_; }
  const glm::dvec3& collar() const { return collar_; }
  const RootParameters& parameters() const { return parameters_; }
  std::span<const RootSegment> segments() const { return segments_; }
  int year() const { return year_; }  // the last year grown (the planting year at first)
  double age_of(const RootSegment& segment) const { return year_ - segment.birth_year; }

  // Crown–root coupling (Root_n of seed 003): added to the branching frequency of every apex in path n.
  void set_branching_bonus(const std::array<double, path_count>& bonus) { branching_bonus_ = bonus; }
  const std::array<double, path_count>& branching_bonus() const { return branching_bonus_; }

  std::vector<RootBud> buds(int year, std::uint64_t seed) const;
  void add_segment(const RootBud& bud, const glm::dvec3& direction, int year, const SoilGrid& soil);
  int finish_year(int year);  // returns the number of segments that died

  // Path (0..7) of a segment: the compass sector (geometry/compass_sector.hpp) of the direction in which its route
  // leaves the main root; no_sector
  // for the main root itself.
  int sector_of_tip(int segment) const { return segments_.at(segment).sector; }

  // W_j = absorptive weight of the type × length × exp(−age / τ_u): capacity sits at the young tips.
  double uptake_capacity(const RootSegment& segment) const;
  // Σ W_j per path (before seed 003's coefficient τ); the main root's own capacity is split evenly.
  std::array<double, path_count> uptake_capacity_by_path() const;

  // The same weighted by what the soil offers at each segment's tip (moisture × nutrient, both 0..1):
  // seed 003's single "water and nutrient" level of the voxels, so that richer soil (Fig. 13, 0.5 → 1.0)
  // gives the crown more from the same roots.
  std::array<double, path_count> available_uptake_by_path(const SoilGrid& soil) const;

  // Removes segments by the rule and everything they carry; returns how many were removed.
  int prune(const RootPruning& rule);

  // Young segments deplete moisture and nutrients at their tips (docs/roots.md); returns moisture taken.
  double take_up(SoilGrid& soil) const;
  // The same in two steps: what each absorbing segment takes of the vertices around its tip (reads the soil's
  // geometry only: the trees' shares can be found in parallel), then the depletion itself, which reads and writes
  // the soil and so goes tree after tree in the stand's order. Returns the moisture taken.
  std::vector<SoilGrid::DepletionShares> uptake_shares(const SoilGrid& soil) const;
  static double take_up(SoilGrid& soil, std::span<const SoilGrid::DepletionShares> shares);

  double total_length_m() const;

 private:
  friend struct checkpoint::Access;
  void remove_dead_and_compact();
  void sprout_fine_roots(int segment, RandomStream& random, std::vector<RootBud>& buds) const;

  int tree_id_;
  glm::dvec3 collar_;
  RootParameters parameters_;
  int year_;
  std::uint64_t next_id_ = 0;
  std::vector<RootSegment> segments_;
  std::array<double, path_count> branching_bonus_{};
};

// The end of a segment from `start` along `direction`, kept inside the soil: a component that would
// leave the grid (or rise above `min_depth_m` below the surface) is reflected, then the end is clamped.
glm::dvec3 keep_in_soil(const glm::dvec3& start, const glm::dvec3& direction, double length, const SoilGrid& soil,
                        double min_depth_m);

}  // namespace heliostand::roots
