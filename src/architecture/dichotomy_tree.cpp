#include "architecture/dichotomy_tree.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geometry/angles.hpp"
#include "geometry/vertical.hpp"
#include "rng/random_stream.hpp"

namespace heliostand {

namespace {
enum Stream : std::uint64_t { kThresholds = 1, kVerticalPlanes = 2 };
}  // namespace

DichotomyTree::DichotomyTree(std::vector<BudStart> starts, double branching_angle_deg, std::uint64_t seed)
    : starts_(std::move(starts)), branching_angle_rad_(radians(branching_angle_deg)), seed_(seed) {
  // Starts that exist from generation 0 (root branches) never face the death rule: threshold -inf.
  for (const BudStart& start : starts_)
    if (start.sprout_generation == 0)
      add_branch(-1, start.group, start.position,
                 start.position + glm::normalize(start.direction) * start.length_factor, -INFINITY);
}

int DichotomyTree::add_branch(int parent, int group, glm::dvec3 base, glm::dvec3 tip, double threshold) {
  DichotomyBranch branch;
  branch.base = base;
  branch.tip = tip;
  branch.parent = parent;
  branch.group = group;
  branch.generation = generation_;
  branch.threshold = threshold;
  if (parent >= 0) {
    ++branches_[parent].children;
    ++branches_[parent].living_children;
  }
  branches_.push_back(branch);
  return static_cast<int>(branches_.size()) - 1;
}

glm::dvec3 DichotomyTree::direction(int index) const {
  return glm::normalize(branches_[index].tip - branches_[index].base);
}

// The branching plane contains the parent and the horizontal line across it, so its steepest slope runs along
// the parent. A vertical parent has no steepest slope: its plane gets a random azimuth.
std::array<glm::dvec3, 2> DichotomyTree::child_directions(int parent) {
  const glm::dvec3 along = direction(parent);
  glm::dvec3 across = glm::cross(along, vertical_up);
  if (glm::length(across) < 1e-9) {
    RandomStream random(seed_, {kVerticalPlanes, static_cast<std::uint64_t>(generation_),
                                static_cast<std::uint64_t>(parent)});
    const double azimuth = random.uniform(0.0, 2.0 * pi);
    across = {std::cos(azimuth), std::sin(azimuth), 0.0};
  }
  across = glm::normalize(across);
  const double c = std::cos(branching_angle_rad_), s = std::sin(branching_angle_rad_);
  return {c * along + s * across, c * along - s * across};
}

std::vector<int> DichotomyTree::add_generation(const DeathThreshold& threshold) {
  const std::vector<int> parents = tips();
  ++generation_;
  RandomStream random(seed_, {kThresholds, static_cast<std::uint64_t>(generation_)});
  std::vector<int> added;
  for (int parent : parents) {
    const glm::dvec3 from = branches_[parent].tip;
    for (const glm::dvec3& d : child_directions(parent))
      added.push_back(add_branch(parent, branches_[parent].group, from, from + d, threshold.draw(random)));
  }
  for (const BudStart& bud : starts_)
    if (bud.sprout_generation == generation_)
      added.push_back(add_branch(-1, bud.group, bud.position,
                                 bud.position + glm::normalize(bud.direction) * bud.length_factor,
                                 threshold.draw(random)));
  return added;
}

std::vector<int> DichotomyTree::tips() const {
  std::vector<int> result;
  for (std::size_t i = 0; i < branches_.size(); ++i)
    if (branches_[i].alive && branches_[i].children == 0) result.push_back(static_cast<int>(i));
  return result;
}

std::vector<LeafBall> DichotomyTree::leaf_balls(const std::vector<int>& branches, double radius) const {
  std::vector<LeafBall> balls;
  balls.reserve(branches.size());
  for (int i : branches) balls.push_back({branches_[i].tip, radius});
  return balls;
}

void DichotomyTree::remove_branch(int index) {
  if (index < 0 || index >= static_cast<int>(branches_.size()))
    throw std::out_of_range("DichotomyTree::remove_branch: no branch " + std::to_string(index));
  // Walk toward the root while the parent is left with no living child (Fig. 9).
  while (index >= 0 && branches_[index].alive) {
    branches_[index].alive = false;
    const int parent = branches_[index].parent;
    if (parent < 0) break;
    if (--branches_[parent].living_children > 0) break;
    index = parent;
  }
}

void DichotomyTree::remove_group(int group) {
  for (auto& branch : branches_)
    if (branch.group == group) branch.alive = false;
  for (auto& start : starts_)
    if (start.group == group) start.sprout_generation = -1;  // its dormant buds go too
}

void DichotomyTree::turn_branch(int index, glm::dvec3 new_direction) {
  DichotomyBranch& branch = branches_[index];
  const double length = glm::length(branch.tip - branch.base);
  branch.tip = branch.base + glm::normalize(new_direction) * length;
}

}  // namespace heliostand
