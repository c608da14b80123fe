#pragma once
// What a hollow is, as a user (scenario, survey table) gives it, and the checks that reject impossible ones.
//
// Units: the seed states sizes in unnamed "units" (W, H ≥ 4, r ≥ 1, 0.1 units of arc per outline step).
// We read one seed unit as one centimetre (seed_unit_m): a 4 cm minimum wound, ≥ 1 cm callus roll and a
// 1 mm outline step are the sizes of real cavity entrances (see docs/hollows.md).
#include <cstdint>
#include <string>
#include <vector>

#include "core/input_error.hpp"

namespace heliostand::hollow {

class TrunkSurface;

inline constexpr double seed_unit_m = 0.01;

enum class Placement {
  cylindrical,    // outline laid in the stem's own (arc length, height) coordinates: any width up to ~80 % of
                  // the circumference (our extension)
  tangent_plane,  // the seed's method: plane perpendicular to line L at A, vertices projected from B
};

struct HollowSpec {
  double height_m = 1.3;              // height of the outline's centre above the ground
  double azimuth_deg = 0.0;           // direction the wound faces, counter-clockwise from east (+x)
  double width_m = 0.12;              // W, outline width (arc length along the circumference)
  double wound_height_m = 0.20;       // H, outline height
  double callus_radius_m = 0.015;     // r, callus roll radius, 1 seed unit ≤ r ≤ W/4
  double bulge_m = 0.01;              // I, extra callus where the rim runs vertically, 0 ≤ I ≤ W/4 − r
  int polygon_corners = 8;            // M, corners of each callus polygon, 4..36
  double bark_line_spacing_m = 0.015; // l, spacing of bark lines
  double bark_segment_m = 0.01;       // q, segment length of bark lines
  double outline_step_m = 0.001;      // arc length per outline vertex; the seed's 0.1 units
  double surface_tolerance_m = 0.0005;// bark/trunk faces are subdivided until this close to the surface
  Placement placement = Placement::cylindrical;
  std::uint64_t seed = 0;             // random stream seed (the lead derives it from run seed + tree id)
};

// Largest callus radius the spec can produce before geometric limits (radius jitter 1.1·r plus full bulge I,
// times the buttress flare at the hollow's lowest point).
double nominal_max_callus_radius(const HollowSpec& spec, const TrunkSurface& trunk);

// Every problem with the spec on this trunk, each naming the HollowSpec field (file and line left empty for
// the caller to fill). Empty when the hollow can be built.
std::vector<InputProblem> validate(const HollowSpec& spec, const TrunkSurface& trunk);

}  // namespace heliostand::hollow
