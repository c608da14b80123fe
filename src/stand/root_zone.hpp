#pragma once
// The roots of every tree of the stand in one shared soil, and each tree's crown–root balance (seed 003
// + docs/roots.md). The stand manager drives it once a year after the light solve:
//
//   RootZone zone(settings, plot, seed, sky_scale, backend);   // the run's compute backend, as for light
//   zone.establish(stand);             // spin-up: roots grown from each tree's planting to the survey age
//   zone.couple(stand);                // year 0: balance only (Branch_n for the first crown step)
//   each year:  stand.grow_year(); stand.illuminate(solver); zone.grow_year(stand);
//
// grow_year: root pruning events of this age → per tree LP_n (this year's leaf-ball light) and WP_n (the
// roots' available uptake) → Root_n to the roots now, Branch_n to the crown for next year's flush → roots of
// all living trees grow one year together → soil recharge. Removed and dead trees' roots are dropped.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "compute/compute_backend.hpp"
#include "core/checkpoint_access.hpp"
#include "coupling/crown_root_balance.hpp"
#include "geometry/plot_bounds.hpp"
#include "records/stand_snapshot.hpp"
#include "roots/root_field_solver.hpp"
#include "roots/root_system.hpp"
#include "roots/soil_grid.hpp"
#include "scenario/roots_settings.hpp"
#include "stand/stand.hpp"

namespace heliostand {

// Per-tree numbers for trees.csv.
struct TreeRootSummary {
  double length_m = 0;      // total length of living root segments
  double max_depth_m = 0;   // deepest segment end below the surface
  double uptake = 0;        // Σ_n available uptake (Σ W_j × moisture × nutrient, before τ): what WP_n sums
};

class RootZone {
 public:
  // The root-contact field runs on `backend` (the device the stand's light runs on).
  RootZone(RootsSettings settings, const PlotBounds& plot, std::uint64_t seed, double sky_scale,
           const compute::ComputeBackend& backend);
  ~RootZone();
  RootZone(RootZone&&) noexcept;

  // Spin-up: every tree gets a root system planted at (stand age − tree age) and all grow together,
  // uncoupled (Root_n = 0), to the current stand age. Call once, before the first couple().
  void establish(const Stand& stand);
  // The crown–root balance of every living tree from its current light and roots (sets both bonuses).
  void couple(Stand& stand);
  // One year (after stand.grow_year() and stand.illuminate()).
  void grow_year(Stand& stand);

  const roots::SoilGrid& soil() const { return soil_; }
  const roots::RootSystem* roots_of(int tree_id) const;
  const PathBalance* balance_of(int tree_id) const;  // last couple(); null when not computed
  TreeRootSummary summary_of(int tree_id) const;
  std::vector<const roots::RootSystem*> living_roots() const;

  // Fills the root columns of trees.csv for the trees of an output year.
  void annotate(StandSnapshot& snapshot) const;

 private:
  friend struct checkpoint::Access;
  void drop_gone_trees(const Stand& stand);
  void prune(const Stand& stand);
  void grow_roots_of(const std::vector<roots::RootSystem*>& trees, int year);

  RootsSettings settings_;
  std::uint64_t seed_;
  double sky_scale_;
  roots::SoilGrid soil_;
  std::unique_ptr<roots::RootFieldSolver> solver_;
  std::vector<std::optional<roots::RootSystem>> roots_;  // by tree id
  std::vector<std::optional<PathBalance>> balance_;      // by tree id
};

// The soil grid under the plot as the settings describe it (fields, then the CSV patch if any).
roots::SoilGrid make_soil(const SoilSettings& settings, const PlotBounds& plot);

}  // namespace heliostand

namespace heliostand {

struct Scenario;

// The stand's root zone as the scenario asks, not yet spun up (a resumed run restores it from a checkpoint);
// nullopt when roots are off.
std::optional<RootZone> make_root_zone(const Scenario& scenario, const compute::ComputeBackend& backend);

// The stand's root zone as the scenario asks ([roots] enabled, soil, coupling, pruning), established
// (spun up) under the stand, its root-contact field on `backend`; nullopt when roots are off.
std::optional<RootZone> establish_root_zone(const Scenario& scenario, const Stand& stand,
                                            const compute::ComputeBackend& backend);

}  // namespace heliostand
