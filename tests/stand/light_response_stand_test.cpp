// Seed 000's light response at stand scale (docs/model.md, "Growth from light"): a thinning gap is filled by the
// neighbours' crowns (Fig. 11 at stand scale), and a suppressed tree in a dense group dies of light while the same
// tree grown in the open keeps its crown. Small young stands and a coarse sky keep the reference solver fast.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "light/reference_light_solver.hpp"
#include "stand/production_sky.hpp"
#include "stand/stand.hpp"
#include "stand/stand_year.hpp"

namespace heliostand {
namespace {

constexpr std::uint64_t response_seed = 5;

using testing::coarse_sky;

StandTree planted(int id, glm::dvec3 position, double site_asymptote_m, int age) {
  TreeCalibration calibration;
  calibration.site_asymptote_m = site_asymptote_m;
  ConiferTree tree(SpeciesParameters{}, calibration, position, response_seed, id);
  tree.grow_to_age(age);
  return StandTree{id, std::to_string(id), "todomatsu", std::move(tree)};
}

// Grows the stand `years` years through the simulated year itself (stand/stand_year.hpp, no roots, nothing
// written); returns the deaths.
std::vector<TreeEvent> grow_with_light(Stand& stand, int years) {
  ReferenceLightSolver solver(coarse_sky());
  StageClock clock;
  StandYear simulated_year(stand, solver, solver, nullptr, nullptr, {response_seed, 1.0, years, 1}, clock);
  std::vector<TreeEvent> deaths;
  for (int year = 0; year <= years; ++year) {
    const auto result = simulated_year.run(year);
    deaths.insert(deaths.end(), result.events.begin(), result.events.end());
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
  const double with_neighbour = reach_toward_plus_x(control.trees()[0].conifer);
  const double into_gap = reach_toward_plus_x(thinned.trees()[0].conifer);
  std::cerr << "reach toward the gap: " << into_gap << " m (thinned) vs " << with_neighbour << " m (control)\n";
  EXPECT_GT(into_gap, with_neighbour + 0.05);
}

TEST(LightResponseStand, SuppressedTreeInADenseGroupFallsBehindButNotInTheOpen) {
  // A short 10-year tree (site asymptote 12 m) at the centre of eight tall ones (32 m), 1.2 m apart (7 000 stems/ha):
  // in their shade its leader and stem grow less than the same tree alone; alone it keeps its crown.
  auto centre_tree = [] {
    StandTree tree = planted(4, {0.0, 0.0, 0.0}, 12.0, 10);
    tree.conifer.set_light_driven_crown(true);
    return tree;
  };
  std::vector<StandTree> group;
  int id = 0;
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j, ++id) {
      group.push_back(i == 0 && j == 0 ? centre_tree() : planted(id, {1.2 * i, 1.2 * j, 0.0}, 32.0, 10));
      group.back().conifer.set_light_driven_crown(true);
    }
  Stand dense(0.01, 10, std::move(group), {});
  std::vector<StandTree> alone;
  alone.push_back(centre_tree());
  Stand open(0.01, 10, std::move(alone), {});

  const double start_height = dense.trees()[4].conifer.height_m(), start_dbh = dense.trees()[4].conifer.dbh_cm();
  grow_with_light(dense, 2);
  EXPECT_TRUE(grow_with_light(open, 2).empty());
  const ConiferTree& shaded = dense.trees()[4].conifer;
  const ConiferTree& lone = open.trees()[0].conifer;
  std::cerr << "after 2 years: height growth " << shaded.height_m() - start_height << " m shaded vs "
            << lone.height_m() - start_height << " m alone; DBH growth " << shaded.dbh_cm() - start_dbh << " vs "
            << lone.dbh_cm() - start_dbh << " cm\n";
  EXPECT_LT(shaded.height_m() - start_height, 0.8 * (lone.height_m() - start_height));
  EXPECT_LT(shaded.dbh_cm() - start_dbh, 0.8 * (lone.dbh_cm() - start_dbh));

  EXPECT_TRUE(grow_with_light(open, 10).empty());
  EXPECT_TRUE(open.trees()[0].alive());
  EXPECT_TRUE(open.trees()[0].conifer.has_living_branch_foliage());
}

// The same suppressed centre tree dies within 12 years: its stem nearly stops thickening, and suppression mortality
// follows its recent growth (or all its foliage dies).
TEST(LightResponseStand, SuppressedTreeInADenseGroupDiesWithinTwelveYears) {
  std::vector<StandTree> group;
  int id = 0;
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j, ++id) {
      group.push_back(planted(id, {1.2 * i, 1.2 * j, 0.0}, i == 0 && j == 0 ? 12.0 : 32.0, 10));
      group.back().conifer.set_light_driven_crown(true);
    }
  Stand dense(0.01, 10, std::move(group), {});
  const auto deaths = grow_with_light(dense, 12);
  ASSERT_FALSE(deaths.empty());
  EXPECT_EQ(deaths.front().label, "4");  // the suppressed centre tree dies first
  EXPECT_TRUE(deaths.front().reason == "suppression" || deaths.front().reason == "light") << deaths.front().reason;
}

}  // namespace
}  // namespace heliostand
