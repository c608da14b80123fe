#pragma once
// Seed 000's simple dichotomy model (Kanamaru et al. 1991, Figs. 7-9): every generation each living tip gets
// two children in its branching plane (the plane through the parent whose steepest-slope direction is the
// parent's direction), each at the branching angle from the parent's extension. Branches carry a leaf ball at
// their tip while they are tips. Light decides (kanamaru_growth.hpp) which new children die — removal runs
// recursively toward the root when both children of a parent are gone — and turns the others by heliotropism.
// Lengths are in branch lengths (1 = one branch); a scene may hold several starts (buds, or two trees: Fig. 11).
#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "architecture/bud_starts.hpp"
#include "architecture/death_threshold.hpp"
#include "architecture/shoot.hpp"

namespace heliostand {

struct DichotomyBranch {
  glm::dvec3 base{0.0};
  glm::dvec3 tip{0.0};
  int parent = -1;          // index of the parent branch; -1 for the first branch of a start
  int group = 0;            // the start's group (tree or bud cluster)
  int generation = 0;       // generation it was added in
  int children = 0;         // children added to it (0 while it is a tip)
  int living_children = 0;
  double threshold = 0;     // its own death threshold D
  bool alive = true;        // removed branches stay in the list, dead
};

class DichotomyTree {
 public:
  DichotomyTree(std::vector<BudStart> starts, double branching_angle_deg, std::uint64_t seed);

  int generation() const { return generation_; }
  const std::vector<DichotomyBranch>& branches() const { return branches_; }

  // Generation + 1: two children on every living tip, and the buds whose time has come sprout their first
  // branch. Returns the new branches; each draws its own death threshold.
  std::vector<int> add_generation(const DeathThreshold& threshold);

  std::vector<int> tips() const;                         // living branches without children
  std::vector<LeafBall> leaf_balls(const std::vector<int>& branches, double radius) const;  // one per branch tip
  // Removes a branch; a parent left without living children is removed too, toward the root.
  void remove_branch(int index);
  // Removes every branch of a group (Fig. 11: the left tree is cut).
  void remove_group(int group);
  // Turns a tip branch about its base to a new direction, keeping its length.
  void turn_branch(int index, glm::dvec3 direction);
  glm::dvec3 direction(int index) const;

 private:
  int add_branch(int parent, int group, glm::dvec3 base, glm::dvec3 tip, double threshold);
  std::array<glm::dvec3, 2> child_directions(int parent);

  std::vector<BudStart> starts_;
  double branching_angle_rad_;
  std::uint64_t seed_;
  int generation_ = 0;
  std::vector<DichotomyBranch> branches_;
};

}  // namespace heliostand
