#pragma once
// A shoot is one annual segment of a branch axis: the unit that flushes, carries foliage (a leaf ball
// at its tip while it is alive and growing), thickens, dies and falls.
#include <glm/vec3.hpp>

#include "light/leaf_ball.hpp"  // a living shoot's foliage, as the light field sees it

namespace heliostand {

struct Shoot {
  glm::dvec3 base{0.0};     // m, stand coordinates (x east, y north, z up)
  glm::dvec3 tip{0.0};      // m
  double base_radius_m = 0; // wood radius at base and tip (eq. 2 for the stem, eq. 11 for branches)
  double tip_radius_m = 0;
  int parent = -1;          // index of the parent shoot in the tree's shoot list; -1 for the stem base
  int axis = 0;             // index of the branch axis (0 = stem) the shoot belongs to
  int order = 0;            // 0 stem, 1 first-order branch, 2 second-order, ...
  int year_formed = 0;      // tree age in the year it flushed
  bool alive = true;        // dead shoots persist until they fall (eq. 13)
  // The light of the shoot's foliage from the latest light field of the stand (the shoot's own leaf ball, or
  // for a shoot without one the ball of the shoot that bears it). 1 before any light has been computed:
  // a tree grown alone (establishment, seed experiments) grows at its open-grown rate.
  double light = 1.0;           // Σ B S / Σ B0 S of the ball in the stand, 0..1
  double relative_light = 1.0;  // light in the stand / light with its tree alone under the reference sky, 0..1
  glm::dvec3 light_vector{0.0, 0.0, 1.0};  // normalize(Σ N B S) of the same ball: where its light comes from
};

}  // namespace heliostand
