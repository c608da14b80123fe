#pragma once
// The direction of a new root segment (seed 003):
//   V = α Vn + β Vg + γ Vd + δ Vw + ε Vt,   α+β+γ+δ+ε = 1, every V* a unit vector, V normalised.
#include <glm/vec3.hpp>

#include "rng/random_stream.hpp"
#include "roots/root_parameters.hpp"

namespace heliostand::roots {

inline constexpr glm::dvec3 gravity_direction{0.0, 0.0, -1.0};  // Vg

struct TropismVectors {
  glm::dvec3 inherited{0.0, 0.0, -1.0};  // Vn (unit)
  glm::dvec3 diagravitropic{1.0, 0.0, 0.0};  // Vd (unit)
  glm::dvec3 moisture_pull{0.0};         // Vw before normalisation (zero: no pull)
  glm::dvec3 contact_avoidance{0.0};     // Vt before normalisation (zero: nothing felt)
};

// Vn: `parent` rotated away from itself by an angle uniform in [min, max] about a uniformly random
// axis perpendicular to it.
glm::dvec3 rotate_within_range(const glm::dvec3& parent, const AngleRangeDeg& range, RandomStream& random);

// Vd: `direction` rotated in its own vertical plane to the horizontal. A vertical direction has no
// vertical plane of its own; it gets the horizontal `fallback` (a random azimuth drawn by the caller).
glm::dvec3 horizontal_of(const glm::dvec3& direction, const glm::dvec3& fallback);

// A unit vector, or zero when the sum is shorter than `negligible`: an empty or balanced field pulls
// nowhere. The threshold sits far above float round-off (≈1e-6 for 16 probes of moisture ≈ 1), so a
// balanced field gives no direction on either backend, and far below any real pull (≥ 1e-2).
inline constexpr double negligible_field = 1e-4;
glm::dvec3 unit_or_zero(const glm::dvec3& v, double negligible = negligible_field);

// Combines the five terms; if they cancel exactly, the inherited direction Vn is kept.
glm::dvec3 compose_direction(const TropismWeights& weights, const TropismVectors& vectors);

}  // namespace heliostand::roots
