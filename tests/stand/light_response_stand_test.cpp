// Seed 000's light response at stand scale (MODEL.md §5): a thinning gap is filled by the neighbours' crowns
// (Fig. 11 at stand scale), and a suppressed tree in a dense group dies of light while the same tree grown in the
// open keeps its crown. Small young stands and a coarse sky keep the reference solver fast.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "light/reference_light_solver.hpp"
#include "stand/stand.hpp"

namespace heliostand {
namespace {

constexpr std::uint64_t seed = 5;

LightParameters coarse_sky() {
  LightParameters light;
  light.sky_bands = 4;
  light.sky_sectors = 8;
  return light;
}

StandTree planted(int id, glm::dvec3 position, double site_asymptote_m, int age) {
  TreeCalibration calibration;
  calibration.site_asymptote_m = site_asymptote_m;
  ConiferTree tree(SpeciesParameters{}, calibration, position, seed, id);
  tree.grow_to_age(age);
  return StandTree{id, std::to_string(id), "todomatsu", std::move(tree)};
}

// Grows the stand `years` years with the light response; returns the deaths.
std::vector<TreeEvent> grow_with_light(Stand& stand, int years) {
  ReferenceLightSolver solver(coarse_sky());
  std::vector<TreeEvent> deaths;
  for (int year = 0; year < years; ++year) {
    stand.grow_year();
    stand.illuminate(solver);
    const auto died = stand.respond_to_light(solver, seed);
    deaths.insert(deaths.end(), died.begin(), died.end());
  }
  return deaths;
}

// How far the tree's living foliage reaches along +x from its stem (the farthest leaf-ball centre).
double reach_toward_plus_x(const ConiferTree& tree) {
  double reach = 0.0;
  for (const LeafBall& ball : tree.leaf_balls()) reach = std::max(reach, ball.centre.x - tree.stem_base().x);
  return reach;
}

TEST(LightResponseStand, NeighboursCrownExtendsIntoAThinningGap) {
  // A row of three 8-year trees 1.5 m apart; the middle one is thinned (it simply is not planted) in one stand and
  // kept in the control. The left tree's crown toward the gap is compared after 4 years.
  auto row = [](bool thinned) {
    std::vector<StandTree> trees;
    trees.push_back(planted(0, {0.0, 0.0, 0.0}, 24.0, 8));
    if (!thinned) trees.push_back(planted(1, {1.5, 0.0, 0.0}, 24.0, 8));
    trees.push_back(planted(2, {3.0, 0.0, 0.0}, 24.0, 8));
    return Stand(0.01, 8, std::move(trees), {});
  };
  Stand control = row(false), thinned = row(true);
  grow_with_light(control, 4);
  grow_with_light(thinned, 4);
  const double with_neighbour = reach_toward_plus_x(control.trees()[0].tree);
  const double into_gap = reach_toward_plus_x(thinned.trees()[0].tree);
  std::cerr << "reach toward the gap: " << into_gap << " m (thinned) vs " << with_neighbour << " m (control)\n";
  EXPECT_GT(into_gap, with_neighbour + 0.05);
}

TEST(LightResponseStand, SuppressedTreeInADenseGroupDiesOfLightButNotInTheOpen) {
  // A short 6-year tree (site asymptote 12 m) at the centre of eight tall ones (32 m), 1.2 m apart (7 000 stems/ha):
  // its leader stays below its threshold (relative light 0.05-0.11 measured) and it dies after 3 years.
  std::vector<StandTree> group;
  int id = 0;
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j, ++id)
      group.push_back(planted(id, {1.2 * i, 1.2 * j, 0.0}, i == 0 && j == 0 ? 12.0 : 32.0, 6));
  Stand dense(0.01, 6, std::move(group), {});
  const auto deaths = grow_with_light(dense, 4);
  ASSERT_FALSE(deaths.empty());
  // The light samples stay one per leaf ball after shoots died (the outputs pair them).
  for (const StandTree& tree : dense.trees())
    if (tree.alive()) EXPECT_EQ(tree.leaf_ball_light.size(), tree.tree.leaf_balls().size()) << tree.label;
  EXPECT_EQ(deaths.front().label, "4");  // the suppressed centre tree dies first
  EXPECT_EQ(deaths.front().kind, TreeEventKind::died);
  EXPECT_EQ(deaths.front().reason, "light");
  EXPECT_EQ(dense.trees()[4].status, TreeStatus::dead);

  std::vector<StandTree> alone;
  alone.push_back(planted(4, {0.0, 0.0, 0.0}, 12.0, 6));
  Stand open(0.01, 6, std::move(alone), {});
  EXPECT_TRUE(grow_with_light(open, 4).empty());
  EXPECT_TRUE(open.trees()[0].alive());
  EXPECT_TRUE(open.trees()[0].tree.has_living_branch_foliage());
}

}  // namespace
}  // namespace heliostand
