#pragma once
// The callus bulge (seed 004, eqs. 3.9–3.11): at every outline vertex V_j an M-gon C_j around the rim's
// direction, its radius jittered per corner and swollen by E_j where the rim runs vertically (the callus
// carries the load the rotten core no longer does).
//
//   N^j_m = Q(θ_m, G_j) T_j R_m + V_j,  θ_m = m·360°/M + c_m,  R_m = r·a + E_j,
//   E_j = I · (|F̂_{j−1}·z| + |F̂_j·z| + |F̂_{j+1}·z|) / 3.
//
// Beyond the seed: radii are limited so that no polygon crosses the plane of a neighbouring one (the seed's
// "thick callus self-intersects"), and they are scaled by the buttress flare near the root collar.
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "hollow/hollow_spec.hpp"
#include "hollow/stem_chart.hpp"
#include "rng/random_stream.hpp"

namespace heliostand::hollow {

struct CallusRing {
  glm::dvec2 centre_xy;            // V_j in stem-chart coordinates
  glm::dvec3 centre;               // V_j on the surface
  glm::dvec3 axis;                 // unit rim direction at V_j (polygon normal)
  glm::dvec2 foot_xy;              // chart position of corner 0, where the bark joins
  double bulge = 0.0;              // E_j (m, before the flare)
  double flare = 1.0;              // buttress factor at V_j
  double limit_scale = 1.0;        // smallest radius reduction applied by the crossing limits (1 = none)
  std::vector<double> theta;       // θ_m, radians, m = 0..M−1 (θ_0 = 0 is the bark side on the surface)
  std::vector<double> jitter;      // a_m ∈ [0.9, 1.1] (a_0 = 1)
  std::vector<double> radius;      // R_m after limits
  std::vector<glm::dvec3> corners; // N^j_m for the emitted corners m = 0..lip_corner
  std::vector<glm::dvec3> directions; // unit Q(θ_m, G_j) T_j for the emitted corners
};

struct Callus {
  std::vector<CallusRing> rings;  // one per outline vertex, in outline order (counter-clockwise in the chart)
  int lip_corner = 0;             // last emitted corner: the roll ends pointing into the wood (θ ≈ 270°)
  double mean_radius(int j) const;  // R_j of eq. 3.18: mean corner radius of ring j
};

// Angle offsets c_m: c_0 = 0, |c_m| ≤ 5°, Σ c_m = 0, and θ_m non-decreasing (M ≤ 36). Radians.
std::vector<double> corner_angle_jitter(int corners, RandomStream& rng);

// Shrinks (by 10 % steps, foot excepted) the polygons bounding any stretch of roll (the band between
// polygons j and j+1) that crosses another stretch, until none cross. Returns the number of crossing pairs left (0 when it succeeded).
int separate_polygons(Callus& callus, int max_rounds = 40);

// limit_crossings = false gives the seed's rolls (no plane, bend, across-the-wound or band-crossing limits),
// kept to show the limit being lifted.
Callus build_callus(const std::vector<glm::dvec2>& outline_xy, const StemChart& chart, const HollowSpec& spec,
                    bool limit_crossings = true);

}  // namespace heliostand::hollow
