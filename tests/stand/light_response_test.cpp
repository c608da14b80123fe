// Seed 000's light response on a seed-001 conifer: bending of new shoots, death by threshold with the axis,
// tree death when the foliage is gone. Light is given by hand here; tests/stand/light_response_stand_test.cpp
// runs it in a lit stand.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "geometry/vector_checks.hpp"
#include "light/reference_light_solver.hpp"
#include "stand/light_response.hpp"

namespace heliostand {
namespace {

ConiferTree young_tree(SpeciesParameters species = {}) {
  ConiferTree tree(species, TreeCalibration{}, {0.0, 0.0, 0.0}, 42, 0);
  tree.grow_to_age(8);
  return tree;
}

std::vector<LightSample> uniform_light(const ConiferTree& tree, double light, glm::dvec3 vector) {
  return std::vector<LightSample>(tree.leaf_balls().size(), LightSample{light, vector});
}

// Open-grown reference light 1 everywhere: the relative light is the stand light itself.
std::vector<LightSample> open_light_of(const ConiferTree& tree) { return uniform_light(tree, 1.0, {0.0, 0.0, 1.0}); }

// Light given by hand: the stand and open-grown samples per leaf ball go onto the shoots as Stand::illuminate puts
// them there, then the response runs on the tree.
LightResponseOutcome respond_to_light(ConiferTree& tree, const std::vector<LightSample>& stand,
                                      const std::vector<LightSample>& open, std::uint64_t seed) {
  std::vector<ConiferTree::FoliageLight> light;
  for (std::size_t k = 0; k < stand.size(); ++k)
    light.push_back({stand[k].light, relative_light(stand[k].light, k < open.size() ? open[k].light : 1.0), stand[k].vector});
  tree.set_foliage_light(light);
  return heliostand::respond_to_light(tree, seed);
}

using testing::angle_between;

TEST(LightResponse, LitNewBranchShootsTurnTowardTheLightVectorByI) {
  ConiferTree tree = young_tree();
  const ConiferTree before = tree;
  const glm::dvec3 east{1.0, 0.0, 0.0};
  const auto outcome = respond_to_light(tree, uniform_light(tree, 1.0, east), open_light_of(tree), 1);
  EXPECT_FALSE(outcome.tree_died);
  EXPECT_EQ(outcome.shaded_out, 0);
  ASSERT_GT(outcome.bent, 0);
  int checked = 0;
  for (int s : tree.new_shoot_indices()) {
    const Shoot& old_shoot = before.shoots()[s];
    const Shoot& new_shoot = tree.shoots()[s];
    const glm::dvec3 old_direction = old_shoot.tip - old_shoot.base;
    const glm::dvec3 new_direction = new_shoot.tip - new_shoot.base;
    if (old_shoot.order == 0) {  // the stem stays vertical
      EXPECT_NEAR(glm::length(new_direction - old_direction), 0.0, 1e-12);
      continue;
    }
    EXPECT_NEAR(angle_between(new_direction, east), 0.6 * angle_between(old_direction, east), 1e-9);
    EXPECT_NEAR(glm::length(new_direction), glm::length(old_direction), 1e-12);
    ++checked;
  }
  EXPECT_EQ(checked, outcome.bent);
}

TEST(LightResponse, ShadedNewShootsDieWithTheirAxisAndTheDeadWoodStays) {
  ConiferTree tree = young_tree();
  const std::size_t shoots_before = tree.shoots().size();
  // Light 0 for this year's branch shoots, full light for the rest (the leader is lit).
  const auto foliage = tree.foliage_shoot_indices();
  std::vector<LightSample> light;
  for (int s : foliage) {
    const Shoot& shoot = tree.shoots()[s];
    light.push_back({shoot.order > 0 && shoot.year_formed == tree.age() ? 0.0 : 1.0, {0.0, 0.0, 1.0}});
  }
  const auto outcome = respond_to_light(tree, light, open_light_of(tree), 1);
  EXPECT_GT(outcome.shaded_out, 0);
  EXPECT_GE(outcome.axes_killed, 1);
  EXPECT_FALSE(outcome.leader_shaded);
  EXPECT_FALSE(outcome.tree_died);
  EXPECT_EQ(tree.shoots().size(), shoots_before);  // dead branches persist (they fall later, eq. 13)
  for (int s : tree.new_shoot_indices())
    if (tree.shoots()[s].order > 0) EXPECT_FALSE(tree.shoots()[s].alive);
    else EXPECT_TRUE(tree.shoots()[s].alive);
}

TEST(LightResponse, ThresholdIsD0PlusMinusDither) {
  SpeciesParameters species;
  species.death_threshold = 0.5;
  species.death_threshold_dither = 0.1;
  // Light 0.39 is below every threshold in [0.4, 0.6); light 0.61 above all of them.
  ConiferTree dark = young_tree(species), bright = young_tree(species);
  EXPECT_EQ(respond_to_light(dark, uniform_light(dark, 0.39, {0, 0, 1}), open_light_of(dark), 1).bent, 0);
  const auto lit = respond_to_light(bright, uniform_light(bright, 0.61, {0, 0, 1}), open_light_of(bright), 1);
  EXPECT_EQ(lit.shaded_out, 0);
  EXPECT_GT(lit.bent, 0);
}

TEST(LightResponse, TreeWhoseFoliageIsAllShadedOutDies) {
  ConiferTree tree = young_tree();
  const auto outcome = respond_to_light(tree, uniform_light(tree, 0.0, {0.0, 0.0, 1.0}), open_light_of(tree), 1);
  EXPECT_TRUE(outcome.leader_shaded);
  EXPECT_TRUE(outcome.tree_died);
  EXPECT_FALSE(tree.has_living_branch_foliage());
}

TEST(LightResponse, TreeWhoseLeaderStaysShadedOutDiesAfterTheSuppressedYears) {
  SpeciesParameters species;
  species.suppressed_years_to_death = 3;
  ConiferTree tree = young_tree(species);
  // Leader in the dark, every branch shoot in full light: the branches live, the leader's count runs.
  auto leader_dark = [&] {
    std::vector<LightSample> light;
    for (int s : tree.foliage_shoot_indices()) light.push_back({tree.shoots()[s].order == 0 ? 0.0 : 1.0, {0, 0, 1}});
    return light;
  };
  for (int year = 1; year <= 3; ++year) {
    if (year > 1) tree.grow_year();
    const auto outcome = respond_to_light(tree, leader_dark(), open_light_of(tree), 1);
    EXPECT_TRUE(outcome.leader_shaded);
    EXPECT_EQ(outcome.tree_died, year == 3) << year;
  }
  // A lit year resets the count.
  tree.grow_year();
  respond_to_light(tree, uniform_light(tree, 1.0, {0, 0, 1}), open_light_of(tree), 1);
  EXPECT_EQ(tree.leader_shaded_years(), 0);
}

TEST(LightResponse, RefusesLightForADifferentFoliage) {
  ConiferTree tree = young_tree();
  std::vector<LightSample> too_few(3);
  EXPECT_THROW(respond_to_light(tree, too_few, open_light_of(tree), 1), std::invalid_argument);
}

TEST(LightResponse, DeathActsOnLightRelativeToTheOpenGrownTree) {
  SpeciesParameters species;
  species.death_threshold = 0.5;
  species.death_threshold_dither = 0.1;
  // Stand light 0.2 is dark in absolute terms, but the same tree alone gets 0.25: the neighbours take only a
  // fifth (relative 0.8 >= every threshold in [0.4, 0.6)). With open light 0.5 the relative light is 0.4 - 1e-9.
  ConiferTree kept = young_tree(species), shaded = young_tree(species);
  const auto k = respond_to_light(kept, uniform_light(kept, 0.2, {0, 0, 1}), uniform_light(kept, 0.25, {0, 0, 1}), 1);
  EXPECT_EQ(k.shaded_out, 0);
  const auto s = respond_to_light(shaded, uniform_light(shaded, 0.2 - 1e-9, {0, 0, 1}),
                                  uniform_light(shaded, 0.5, {0, 0, 1}), 1);
  EXPECT_EQ(s.bent, 0);
  EXPECT_GT(s.shaded_out, 0);
}

TEST(LightResponse, OpenGrownLightIsSolvedForEveryLeafBall) {
  ConiferTree tree = young_tree();
  LightParameters parameters;
  parameters.sky_bands = 4;
  parameters.sky_sectors = 8;
  ReferenceLightSolver solver(parameters);
  const auto light = open_grown_light(tree, solver);
  const auto foliage = tree.foliage_shoot_indices();
  ASSERT_EQ(light.size(), foliage.size());
  const auto balls = tree.leaf_balls();
  const auto all = solver.solve(balls);
  // Every ball is solved (the tree's light budget sums all its foliage), against its own crown alone.
  for (std::size_t k = 0; k < foliage.size(); ++k) EXPECT_DOUBLE_EQ(light[k].light, all[k].light);
}

}  // namespace
}  // namespace heliostand
