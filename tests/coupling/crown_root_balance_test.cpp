// Seed 003's 8-path balance: hand-computed Branch_n / Root_n, the guards, and the crown paths of a grown tree.
#include "coupling/crown_root_balance.hpp"

#include <cmath>
#include <numeric>

#include <gtest/gtest.h>

#include "geometry/angles.hpp"

namespace heliostand {
namespace {

TEST(CrownRootBalance, BonusesFollowTheSeedFormulasWithTheCapAtTwo) {
  // LP = 2, WP = 1: Branch = 0.5 (1/2 − 1) = −0.25; Root = 0.5 (min(2, 2) − 1) = 0.5.
  EXPECT_DOUBLE_EQ(branch_bonus(2.0, 1.0, 0.5), -0.25);
  EXPECT_DOUBLE_EQ(root_bonus(2.0, 1.0, 0.5), 0.5);
  // LP = 1, WP = 3: WP/LP = 3 is capped at 2 → Branch = 0.5; Root = 0.5 (1/3 − 1) = −1/3.
  EXPECT_DOUBLE_EQ(branch_bonus(1.0, 3.0, 0.5), 0.5);
  EXPECT_DOUBLE_EQ(root_bonus(1.0, 3.0, 0.5), -1.0 / 3.0);
  // Balanced: both 0. α scales linearly.
  EXPECT_DOUBLE_EQ(branch_bonus(4.0, 4.0, 0.7), 0.0);
  EXPECT_DOUBLE_EQ(root_bonus(1.0, 1.5, 0.3), 0.3 * (1.0 / 1.5 - 1.0));
}

TEST(CrownRootBalance, EmptyPathsAreGuarded) {
  EXPECT_DOUBLE_EQ(branch_bonus(0.0, 0.0, 0.5), 0.0);
  EXPECT_DOUBLE_EQ(root_bonus(0.0, 0.0, 0.5), 0.0);
  // Roots but no light: crown free to branch, roots suppressed.
  EXPECT_DOUBLE_EQ(branch_bonus(0.0, 1.0, 0.5), 0.5);
  EXPECT_DOUBLE_EQ(root_bonus(0.0, 1.0, 0.5), -0.5);
  // Light but no roots (a path pruned bare): crown suppressed, roots pushed.
  EXPECT_DOUBLE_EQ(branch_bonus(1.0, 0.0, 0.5), -0.5);
  EXPECT_DOUBLE_EQ(root_bonus(1.0, 0.0, 0.5), 0.5);
}

TEST(CrownRootBalance, BalanceAppliesRhoAndTauPerPath) {
  PathValues light{}, uptake{};
  light[2] = 100.0;  // ρ = 0.01 → LP = 1
  uptake[2] = 0.5;   // τ = 4 → WP = 2
  light[5] = 300.0;  // LP = 3, WP = 0
  const PathBalance b = balance_paths(light, uptake, {true, 0.01, 4.0, 0.5, 0.25});
  EXPECT_DOUBLE_EQ(b.lp[2], 1.0);
  EXPECT_DOUBLE_EQ(b.wp[2], 2.0);
  EXPECT_DOUBLE_EQ(b.branch[2], 0.5);           // 0.5 (min(2, 2) − 1)
  EXPECT_DOUBLE_EQ(b.root[2], 0.25 * (0.5 - 1.0));
  EXPECT_DOUBLE_EQ(b.branch[5], -0.5);
  EXPECT_DOUBLE_EQ(b.root[5], 0.25);
  EXPECT_DOUBLE_EQ(b.branch[0], 0.0);           // empty path
}

ConiferTree grown_conifer(int age) {
  ConiferTree tree(SpeciesParameters{}, TreeCalibration{}, {3.0, 4.0, 0.0}, 11, 0);
  tree.grow_to_age(age);
  return tree;
}

TEST(CrownRootBalance, EveryFirstOrderShootPointsIntoItsPath) {
  const ConiferTree tree = grown_conifer(12);
  int checked = 0;
  for (std::size_t i = 0; i < tree.shoots().size(); ++i) {
    const Shoot& shoot = tree.shoots()[i];
    const int path = crown_path_of_shoot(tree, static_cast<int>(i));
    if (shoot.order == 0) {
      EXPECT_EQ(path, -1);
      continue;
    }
    ASSERT_GE(path, 0);
    if (shoot.order != 1) continue;
    // A first-order branch grows in its own vertical plane: its tip's azimuth around the stem is its path's.
    const glm::dvec3 offset = shoot.tip - tree.stem_base();
    EXPECT_EQ(compass_sector_of(offset), path) << "shoot " << i;
    ++checked;
  }
  EXPECT_GT(checked, 20);
}

TEST(CrownRootBalance, LateralsTakeThePathOfTheirFirstOrderBranch) {
  const ConiferTree tree = grown_conifer(12);
  int checked = 0;
  for (std::size_t i = 0; i < tree.shoots().size(); ++i) {
    const Shoot& shoot = tree.shoots()[i];
    if (shoot.order < 2) continue;
    int ancestor = shoot.parent;  // walk down to the first-order shoot that carries it
    while (tree.shoots()[static_cast<std::size_t>(ancestor)].order > 1) ancestor = tree.shoots()[static_cast<std::size_t>(ancestor)].parent;
    EXPECT_EQ(crown_path_of_shoot(tree, static_cast<int>(i)), crown_path_of_shoot(tree, ancestor));
    ++checked;
  }
  EXPECT_GT(checked, 20);
}

TEST(CrownRootBalance, LightByPathSumsAbsoluteLightAndSplitsTheLeader) {
  const ConiferTree tree = grown_conifer(10);
  const std::vector<int> shoots = tree.foliage_shoot_indices();
  std::vector<LightSample> light(shoots.size());
  double leader_light = 0.0;
  PathValues expected{};
  for (std::size_t i = 0; i < shoots.size(); ++i) {
    light[i].light = 0.1 + 0.8 * static_cast<double>(i % 7) / 7.0;
    const int path = crown_path_of_shoot(tree, shoots[i]);
    if (path < 0) leader_light += light[i].light;
    else expected[static_cast<std::size_t>(path)] += light[i].light;
  }
  ASSERT_GT(leader_light, 0.0);  // the leader carries foliage
  const PathValues got = light_by_path(tree, light, 0.5);
  double total = 0.0;
  for (std::size_t n = 0; n < 8; ++n) {
    EXPECT_NEAR(got[n], 0.5 * (expected[n] + leader_light / 8.0), 1e-12);
    total += got[n];
  }
  double all = 0.0;
  for (const auto& s : light) all += s.light;
  EXPECT_NEAR(total, 0.5 * all, 1e-9);  // sky ×0.5 halves the light the crown sends down
}

TEST(CrownBranchingBonus, MinusOneStopsEveryLateralInItsPathsOnly) {
  ConiferTree tree(SpeciesParameters{}, TreeCalibration{}, {0.0, 0.0, 0.0}, 5, 0);
  std::array<double, 8> bonus{};
  for (int n : {0, 1, 2, 3}) bonus[static_cast<std::size_t>(n)] = -1.0;  // north-east half suppressed
  tree.set_branching_bonus(bonus);
  tree.grow_to_age(14);
  int suppressed = 0, free = 0;
  for (std::size_t i = 0; i < tree.shoots().size(); ++i) {
    if (tree.shoots()[i].order < 2) continue;
    const int path = crown_path_of_shoot(tree, static_cast<int>(i));
    (path <= 3 ? suppressed : free)++;
  }
  EXPECT_EQ(suppressed, 0);
  EXPECT_GT(free, 50);
}

TEST(CrownBranchingBonus, BonusMovesThirdOrderOccurrenceBothWays) {
  // With the Todomatsu default activity (−9) third-order branches stop at once (eq. 12: 18 − 2·9 = 0
  // years): a weaker growth stop lets them grow, so their occurrence probability is in play.
  SpeciesParameters species;
  species.activity = -4.0;
  auto third_order = [&](double bonus) {
    ConiferTree tree(species, TreeCalibration{}, {0.0, 0.0, 0.0}, 5, 0);
    std::array<double, 8> b;
    b.fill(bonus);
    tree.set_branching_bonus(b);
    tree.grow_to_age(16);
    int n = 0;
    for (const Shoot& s : tree.shoots()) n += s.order == 3;
    return n;
  };
  const int fewer = third_order(-0.5), none = third_order(0.0), more = third_order(0.5);
  EXPECT_LT(fewer, none * 8 / 10);
  EXPECT_GT(more, none);  // most third-order buds already flush with probability 1: a small gain
}

}  // namespace
}  // namespace heliostand
