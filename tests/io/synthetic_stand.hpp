#pragma once
// A tiny hand-made stand for the output tests: conifer-like trees with a stem of one-metre shoots,
// a whorl of four first-order branches at every stem node above 2 m, and a leaf ball at each living
// branch tip. Every count below is known by construction, so tests can check the written files.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "records/stand_snapshot.hpp"

namespace heliostand::testing {

// The shoots of one tree must outlive the snapshot that views them.
struct SyntheticTree {
  std::vector<Shoot> shoots;
  std::vector<LeafBall> balls;
  std::vector<double> light;
  std::vector<int> ball_shoot;  // the index in `shoots` of each ball's shoot
};

inline constexpr int kBranchesPerWhorl = 4;
inline constexpr int kFirstWhorlHeight = 2;  // m: no branches on the lowest two stem shoots

// A tree of `height` whole metres: `height` stem shoots, (height - kFirstWhorlHeight) whorls of four
// branches, one leaf ball per branch (the branches of the lowest whorl are dead and carry no ball).
inline SyntheticTree make_synthetic_tree(glm::dvec3 base, int height) {
  SyntheticTree tree;
  for (int z = 0; z < height; ++z) {
    Shoot stem;
    stem.base = base + glm::dvec3(0, 0, z);
    stem.tip = base + glm::dvec3(0, 0, z + 1);
    stem.base_radius_m = 0.01 * (height - z);
    stem.tip_radius_m = 0.01 * (height - z - 1) + 0.002;
    stem.parent = z - 1;
    stem.axis = 0;
    stem.order = 0;
    stem.year_formed = z;
    tree.shoots.push_back(stem);
  }
  int axis = 1;
  for (int z = kFirstWhorlHeight; z < height; ++z) {
    const double length = 0.4 + 0.2 * (height - z);  // longer branches lower in the crown
    for (int k = 0; k < kBranchesPerWhorl; ++k, ++axis) {
      const double angle = k * std::numbers::pi / 2;
      Shoot branch;
      branch.base = base + glm::dvec3(0, 0, z);
      branch.tip = branch.base + glm::dvec3(length * std::cos(angle), length * std::sin(angle), 0.3);
      branch.base_radius_m = 0.006;
      branch.tip_radius_m = 0.002;
      branch.parent = z - 1;
      branch.axis = axis;
      branch.order = 1;
      branch.year_formed = z;
      branch.alive = z > kFirstWhorlHeight;
      tree.shoots.push_back(branch);
      if (branch.alive) {
        tree.balls.push_back({branch.tip, 0.25});
        tree.light.push_back(std::min(1.0, 0.2 + 0.1 * z));
        tree.ball_shoot.push_back(static_cast<int>(tree.shoots.size()) - 1);
      }
    }
  }
  return tree;
}

// Shoots, branch count and leaf balls of make_synthetic_tree(height).
inline int synthetic_shoot_count(int height) { return height + kBranchesPerWhorl * (height - kFirstWhorlHeight); }
inline int synthetic_ball_count(int height) { return kBranchesPerWhorl * (height - kFirstWhorlHeight - 1); }

inline TreeSnapshot snapshot_of(const SyntheticTree& tree, int id, std::string label, std::string species,
                                glm::dvec3 position, int height, TreeStatus status = TreeStatus::alive) {
  TreeSnapshot s;
  s.id = id;
  s.label = std::move(label);
  s.species = std::move(species);
  s.position = position;
  s.status = status;
  s.age_years = 2.0 * height;
  s.height_m = height;
  s.dbh_cm = 2.0 * height;
  s.crown_base_m = kFirstWhorlHeight + 1;
  s.crown_radius_m = 0.4 + 0.2 * (height - kFirstWhorlHeight - 1);
  s.volume_m3 = 0.001 * height * height;
  s.mean_light = 0.5;
  s.shoots = tree.shoots;
  s.leaf_balls = tree.balls;
  s.leaf_ball_light = tree.light;
  s.leaf_ball_shoot = tree.ball_shoot;
  return s;
}

// Three trees on a 10 m × 10 m plot, two Todomatsu and a Karamatsu (the second); heights grow by one metre every
// two years of stand age.
struct SyntheticStand {
  std::vector<SyntheticTree> trees;
  std::vector<int> heights;
  StandSnapshot snapshot;
};

inline SyntheticStand make_synthetic_stand(int stand_age, int year_index) {
  SyntheticStand stand;
  const glm::dvec3 positions[] = {{2.0, 2.0, 0.0}, {7.0, 3.0, 0.0}, {7.5, 8.0, 0.0}};
  const char* labels[] = {"A-1", "A,2", "B \"3\""};  // labels that need CSV quoting
  const char* species[] = {"todomatsu", "karamatsu", "todomatsu"};
  stand.heights = {stand_age / 2 + 1, stand_age / 2, stand_age / 2 - 1};
  for (int i = 0; i < 3; ++i) stand.trees.push_back(make_synthetic_tree(positions[i], stand.heights[i]));
  stand.snapshot.stand_age = stand_age;
  stand.snapshot.year_index = year_index;
  for (int i = 0; i < 3; ++i) {
    stand.snapshot.trees.push_back(
        snapshot_of(stand.trees[i], i + 1, labels[i], species[i], positions[i], stand.heights[i]));
  }
  return stand;
}

}  // namespace heliostand::testing
