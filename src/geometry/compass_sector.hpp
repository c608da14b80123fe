#pragma once
// The eight compass sectors around a stem, 45° each, counted counter-clockwise from east (+x): sector 0 holds
// azimuths [0°, 45°), sector 2 north (+y), sector 4 west, sector 7 [315°, 360°). The crown–root coupling ties a
// tree's crown and roots through these eight angular paths (docs/roots.md), so architecture (a bough's path),
// roots (a root's path) and coupling (light and uptake per path) must agree on one mapping: this one.
#include <algorithm>
#include <cmath>

#include <glm/vec3.hpp>

#include "geometry/angles.hpp"

namespace heliostand {

inline constexpr int compass_sector_count = 8;

// Any angle in radians (wrapped into [0, 2π) first); an angle that rounds to 2π falls in the last sector.
inline int compass_sector(double azimuth_rad) {
  double azimuth = std::fmod(azimuth_rad, 2.0 * pi);
  if (azimuth < 0.0) azimuth += 2.0 * pi;
  return std::clamp(static_cast<int>(azimuth / (2.0 * pi / compass_sector_count)), 0, compass_sector_count - 1);
}

// The sector of a direction's horizontal part (its z is ignored).
inline int compass_sector_of(const glm::dvec3& direction) { return compass_sector(std::atan2(direction.y, direction.x)); }

}  // namespace heliostand
