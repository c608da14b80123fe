#pragma once
// Bark lines flowing around the wound (seed 004 §3.2.1, eqs. 3.12–3.16, restated as a displacement field).
//
// The seed lays vertical bark lines a spacing l apart across the wound, moves every vertex that falls inside
// the outline sideways to the outline (lines left of the top vertex to the left, the others to the right),
// pushes the neighbouring lines outwards with a push that decays with their distance g′ from the wound, and
// lets lines that ended up more than l from their neighbour relax back. We keep exactly that behaviour in a
// form that cannot fold: the line that starts at x is moved, at height y, to
//
//     X(x, y) = x + sign(x) · w(y) · (1 − |x|/P)^k
//
// where w(y) is how far the callus foot reaches to that side at height y, and P the half-width of the bark
// patch. The innermost lines land just outside the callus, each line further out moves less (the seed's
// decay f), the lines keep their order (dX/dx > 0 because k·w < P), and at |x| ≥ P, as well as above and
// below the wound, lines are back at their original spacing (the seed's relaxation U).
#include <vector>

#include <glm/vec2.hpp>

namespace heliostand::hollow {

// Sideways reach of a closed loop (the callus foot) at each height.
class WoundProfile {
 public:
  explicit WoundProfile(std::vector<glm::dvec2> loop);
  double y_min() const { return y_min_; }
  double y_max() const { return y_max_; }
  int bottom_index() const { return bottom_; }
  int top_index() const { return top_; }
  const std::vector<glm::dvec2>& loop() const { return loop_; }
  double left_reach(double y) const;   // max(0, −min x of the loop at height y); 0 outside [y_min, y_max]
  double right_reach(double y) const;  // max(0, max x of the loop at height y)
  double max_reach() const;

 private:
  std::vector<glm::dvec2> loop_;
  int bottom_ = 0, top_ = 0;
  double y_min_ = 0, y_max_ = 0;
};

class BarkFlow {
 public:
  // patch_half_width: P; lines with |x| ≥ P do not move.
  BarkFlow(const WoundProfile& profile, double patch_half_width);
  double patch_half_width() const { return half_width_; }
  double exponent() const { return exponent_; }
  // Position of the line that starts at x, at height y (x = 0 is the split line through the top vertex).
  double displaced(double x, double y) const;
  // The same with the wound's reach at that height already known (profile.left_reach(y), right_reach(y)).
  double displaced(double x, double left_reach, double right_reach) const;

 private:
  const WoundProfile* profile_;
  double half_width_;
  double exponent_;
};

// Heights at which every bark line gets a vertex inside the wound's height range: added wherever the
// callus foot's reach changed by more than `reach_step` since the last row, so that straight segments of
// a bark line cannot cut across the callus foot between two rows.
std::vector<double> wound_rows(const WoundProfile& profile, double reach_step);

// Seed eq. 3.18: bark near the wound rises by (R_j / 2r) / |V_j − b| (seed units) along the ray from B.
// In metres: 1e-4 · (R_j / 2r) / d, capped at r/2 so that the bark stays below the roll it rolls onto
// (the roll is at least r high) and its rise stays gentle where the bulge makes R_j large.
double seed_bark_lift(double mean_callus_radius, double callus_radius, double distance);

}  // namespace heliostand::hollow
