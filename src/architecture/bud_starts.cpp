#include "architecture/bud_starts.hpp"

#include <cmath>

#include <glm/geometric.hpp>

#include "geometry/angles.hpp"
#include "rng/random_stream.hpp"

namespace heliostand {

glm::dvec3 random_direction(RandomStream& random) {
  const double z = random.uniform(-1.0, 1.0);
  const double azimuth = random.uniform(0.0, 2.0 * pi);
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {r * std::cos(azimuth), r * std::sin(azimuth), z};
}

BudStart root_branch(glm::dvec3 position, double length_factor, int group) {
  BudStart start;
  start.position = position;
  start.length_factor = length_factor;
  start.group = group;
  return start;
}

std::vector<BudStart> bud_sphere(const BudSphere& sphere, std::uint64_t seed, int group) {
  RandomStream random(seed, {0xB0D5u, static_cast<std::uint64_t>(group)});
  std::vector<BudStart> buds;
  for (int i = 0; i < sphere.buds; ++i) {
    // Uniform in the ball: uniform direction, radius ~ cube root of a uniform number. Drawn in two statements:
    // the operands of one `*` are evaluated in an order the compiler chooses, so GCC and clang drew these two in
    // opposite orders and placed the same seed's buds differently.
    const double radius_fraction = std::cbrt(random.uniform());
    const glm::dvec3 direction = random_direction(random);
    const glm::dvec3 offset = direction * sphere.radius * radius_fraction;
    BudStart bud;
    bud.position = sphere.centre + offset;
    bud.direction = random_direction(random);
    bud.sprout_generation = 1 + random.below(sphere.latest_sprouting);
    bud.group = group;
    buds.push_back(bud);
  }
  return buds;
}

std::vector<BudStart> bud_cylinder(const BudCylinder& cylinder, std::uint64_t seed) {
  RandomStream random(seed, {0xC111u});
  std::vector<BudStart> buds;
  for (int i = 0; i < cylinder.buds; ++i) {
    const double azimuth = random.uniform(0.0, 2.0 * pi);
    const glm::dvec3 outward{std::cos(azimuth), std::sin(azimuth), 0.0};
    BudStart bud;
    bud.position = cylinder.base + outward * cylinder.radius + glm::dvec3{0.0, 0.0, random.uniform() * cylinder.height};
    bud.direction = glm::normalize(outward + random_direction(random));
    if (!std::isfinite(bud.direction.x)) bud.direction = outward;
    bud.sprout_generation = 1 + random.below(cylinder.latest_sprouting);
    buds.push_back(bud);
  }
  return buds;
}

}  // namespace heliostand
