#pragma once
// Seed 003 §4: the crown and the roots of one tree talk through 8 virtual paths (45° sectors around the
// trunk and the main root, counter-clockwise from +x/east, the same numbering as roots::RootSystem).
//
// Above ground the trunk is the conifer's leader (the seed picks the trunk as the root-to-tip route of
// highest mean hormone; a conifer's excurrent leader is that route). Every leaf ball's shoot is traced back
// to the trunk: its path is the sector of the azimuth at which its first-order branch leaves the trunk.
// Leaf balls on the leader itself belong to no single path: their light is split evenly over the 8
// (as roots::RootSystem splits the main root's uptake).
#include <array>
#include <span>

#include "architecture/conifer_tree.hpp"
#include "coupling/coupling_parameters.hpp"
#include "geometry/compass_sector.hpp"
#include "light/light_solver.hpp"

namespace heliostand {

// The crown's paths are the compass sectors of its first-order boughs (geometry/compass_sector.hpp), the same as
// the roots' (roots::path_count), so light and uptake of path n meet in one sector.
inline constexpr int crown_path_count = compass_sector_count;
using PathValues = std::array<double, crown_path_count>;

// Path of a shoot: the sector of its first-order branch's azimuth on the trunk; −1 for the trunk itself.
int crown_path_of_shoot(const ConiferTree& tree, int shoot_index);

// Σ L_i per path over the tree's leaf balls. `light` holds one sample per leaf_balls() entry (the stand's
// yearly light solve). L_i = relative light × sky_scale: LightSample::light is a fraction of the unshaded
// sky, in which the sky scale cancels, so the absolute light a ball receives is that fraction × the scale.
PathValues light_by_path(const ConiferTree& tree, std::span<const LightSample> light, double sky_scale);

// One path's balance. Guards (the seed divides without saying what an empty path gives):
//   LP = WP = 0  → 0 (nothing on either side: no signal);
//   LP = 0 < WP  → WP/LP taken as ∞, capped at 2: Branch = +α_b; LP/WP = 0: Root = −α_r;
//   WP = 0 < LP  → Branch = −α_b, Root = +α_r.
double branch_bonus(double lp, double wp, double alpha_b);
double root_bonus(double lp, double wp, double alpha_r);

struct PathBalance {
  PathValues lp{};      // ρ Σ L_i
  PathValues wp{};      // τ Σ W_j
  PathValues branch{};  // Branch_n
  PathValues root{};    // Root_n
};

// LP, WP and both bonuses from the per-path sums (Σ L_i, Σ W_j before ρ and τ).
PathBalance balance_paths(const PathValues& light_sum, const PathValues& uptake_sum, const CouplingParameters& p);

}  // namespace heliostand
