#pragma once
// The stem of a simulated conifer as a surface for hollows and the `trunk` output block: the species'
// own taper (seed 001 eq. 2) scaled to the tree's own DBH (`diameter_scale` = DBH / the taper's DBH, as
// ConiferTree::stem_scale: the same diameters the branches block and the DBH column use) with a root
// collar flare. Every tree of the stand gets its trunk from here, so a hollow is checked at load time
// against the same surface it is later meshed on.
#include "architecture/species.hpp"
#include "hollow/trunk_surface.hpp"

namespace heliostand::hollow {

// Root collar of a grown stem: 30 % wider at the ground, fading over 0.3 m (≈ 0.4 % at breast height, so
// the DBH the tables report is kept). Not in the seeds; a typical collar shape for a pole-size conifer.
inline constexpr Buttress conifer_root_collar{0.3, 0.3};

TrunkSurface conifer_trunk(const SpeciesParameters& species, double tree_height_m, double crown_base_m,
                           double diameter_scale = 1.0);

}  // namespace heliostand::hollow
