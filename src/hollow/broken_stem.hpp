#pragma once
// A hollow all around a broken stem (the case the seed names but cannot build): the stem has snapped at
// break_height_m, its rotten core is open, and the callus rolls over the whole rim of the break. The rim is
// the break's edge on the stem surface, an oblique cut whose height varies by break_tilt_m around the stem,
// so the seed's bulge E_j = I·|F̂_j · z| thickens the roll where the rim runs steeply. As the seed notes,
// the rim runs across the bark's flow, so the bark lines do not detour: they run straight up to the roll.
#include <cstdint>
#include <vector>

#include "hollow/hollow_mesh.hpp"
#include "core/input_error.hpp"

namespace heliostand::hollow {

struct BrokenStemSpec {
  double break_height_m = 6.0;        // mean height of the rim
  double break_tilt_m = 0.10;         // rim height difference across the stem (0 = level break)
  double azimuth_deg = 0.0;           // direction in which the rim is highest
  double callus_radius_m = 0.02;      // r, 1 seed unit ≤ r ≤ stem radius / 4
  double bulge_m = 0.01;              // I, 0 ≤ I ≤ stem radius / 4 − r
  int polygon_corners = 8;            // M
  double bark_line_spacing_m = 0.015; // l
  double bark_segment_m = 0.01;       // q
  double outline_step_m = 0.001;
  double surface_tolerance_m = 0.0005;
  std::uint64_t seed = 0;
};

std::vector<InputProblem> validate(const BrokenStemSpec& spec, const TrunkSurface& trunk);

// The stem from the ground up to the break, bark lines straight up to the roll, the roll all around.
// Throws InputError (field kind "field") when validate() reports problems.
HollowModel build_broken_stem(const BrokenStemSpec& spec, const TrunkSurface& trunk, BuildOptions options = {});

}  // namespace heliostand::hollow
