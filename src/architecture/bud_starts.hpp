#pragma once
// Where the branches of a seed-000 tree start (Kanamaru et al. 1991, §4.1). A start is a bud: a position, an
// initial direction and the generation in which it sprouts its first branch.
//  - a single vertical root branch (the simple dichotomy model, Figs. 7-14; 15x longer in Figs. 10-14);
//  - a bud sphere (Fig. 5): buds at random positions inside a sphere, random directions, random sprouting
//    generation 1..G_s;
//  - bud clusters (Fig. 6a, b): several small bud spheres;
//  - a cylinder surface (Fig. 6c): a trunk pruned of all branches, buds anywhere on its surface.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace heliostand {

struct BudStart {
  glm::dvec3 position{0.0};
  glm::dvec3 direction{0.0, 0.0, 1.0};  // unit
  int sprout_generation = 0;             // 0: exists from the start (the root branch)
  double length_factor = 1.0;            // first branch length in branch lengths (15 for Figs. 10-14's root)
  int group = 0;                         // which tree (Fig. 11) or cluster the bud belongs to
};

// One vertical root branch at `position`, existing from generation 0.
BudStart root_branch(glm::dvec3 position, double length_factor, int group = 0);

struct BudSphere {
  glm::dvec3 centre{0.0};
  double radius = 5.0;          // branch lengths
  int buds = 50;                // Fig. 5: 50
  int latest_sprouting = 20;    // sprouting generation uniform in 1..latest_sprouting (Fig. 5: 20)
};
std::vector<BudStart> bud_sphere(const BudSphere& sphere, std::uint64_t seed, int group = 0);

struct BudCylinder {
  glm::dvec3 base{0.0};
  double radius = 1.0;          // branch lengths
  double height = 10.0;
  int buds = 50;
  int latest_sprouting = 20;
};
// Buds uniform on the lateral surface, pointing outward (a pruned trunk sprouts from its bark) jittered by a
// random direction, so not all branches start horizontal.
std::vector<BudStart> bud_cylinder(const BudCylinder& cylinder, std::uint64_t seed);

// A unit vector uniform on the sphere.
class RandomStream;
glm::dvec3 random_direction(RandomStream& random);

}  // namespace heliostand
