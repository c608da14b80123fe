#pragma once
// Random leaf-ball stands for backend-equivalence tests. The device works in float, the reference in
// double: a patch-centre ray that grazes a ball (or a receiver centre on a ball's surface) could be decided
// differently. These stands are drawn so that no such decision is closer than 1e-4 of the ball radius to
// its threshold (checked in double, against every ball and, for periodic stands, every image across the
// plot edges), so float round-off (~1e-6 of the radius here) cannot flip any.
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "architecture/shoot.hpp"
#include "light/celestial_sphere.hpp"
#include "rng/random_stream.hpp"

namespace heliostand::testing {

inline bool decided_with_margin(const glm::dvec3& receiver, const LeafBall& ball, const CelestialSphere& sky) {
  constexpr double margin = 1e-4;
  const glm::dvec3 d = ball.centre - receiver;
  const double dist = glm::length(d);
  if (std::abs(dist - ball.radius) < margin * ball.radius) return false;
  for (const auto& patch : sky.patches()) {
    const double along = glm::dot(d, patch.direction);
    if (along <= 0) continue;
    const double miss = glm::length(glm::cross(d, patch.direction));
    if (std::abs(miss - ball.radius) < margin * ball.radius) return false;
  }
  return true;
}

// `count` balls with centres uniform in [0, size]^3 and radii in [r_min, r_max].
inline std::vector<LeafBall> random_stand(std::size_t count, double size, double r_min, double r_max,
                                          std::uint64_t seed, const CelestialSphere& sky, bool periodic) {
  RandomStream random(seed, {7});
  std::vector<LeafBall> balls;
  const int reach = periodic ? 1 : 0;
  while (balls.size() < count) {
    const LeafBall candidate{{random.uniform(0, size), random.uniform(0, size), random.uniform(0, size)},
                             random.uniform(r_min, r_max)};
    bool clean = true;
    for (const auto& other : balls)
      for (int sx = -reach; sx <= reach && clean; ++sx)
        for (int sy = -reach; sy <= reach && clean; ++sy) {
          const glm::dvec3 shift(sx * size, sy * size, 0.0);
          clean = decided_with_margin(candidate.centre, {other.centre + shift, other.radius}, sky) &&
                  decided_with_margin(other.centre, {candidate.centre + shift, candidate.radius}, sky);
        }
    // a ball's own images shade it on a torus
    for (int sx = -reach; sx <= reach && clean; ++sx)
      for (int sy = -reach; sy <= reach && clean; ++sy)
        if (sx != 0 || sy != 0)
          clean = decided_with_margin(candidate.centre,
                                      {candidate.centre + glm::dvec3(sx * size, sy * size, 0.0), candidate.radius}, sky);
    if (clean) balls.push_back(candidate);
  }
  return balls;
}

}  // namespace heliostand::testing
