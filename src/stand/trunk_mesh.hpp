#pragma once
// The stem of a stand tree as surface geometry for the `trunk` output block: the species taper at the
// tree's current height and crown base (hollow/conifer_trunk.hpp), carrying the tree's hollows.
#include <memory>

#include "hollow/hollow_mesh.hpp"
#include "stand/stand_tree.hpp"

namespace heliostand {

// Chord tolerance of stems without hollows: 2 mm keeps a 20 cm stem at ~22 facets around, enough for a stand
// overview; a hollow's own patch uses the hollow's (finer) surface_tolerance_m.
inline constexpr double plain_trunk_tolerance_m = 0.002;

// Null for a tree without a stem yet (height 0). A hollow the grown trunk can no longer carry (which the
// load-time check against the surveyed trunk makes unlikely) is left out with a warning, never an abort.
std::shared_ptr<const hollow::HollowMesh> trunk_mesh_of(const StandTree& tree);

}  // namespace heliostand
