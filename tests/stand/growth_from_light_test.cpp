// Growth that follows light (docs/model.md "Growth from light"): the survey is the starting point, released trees
// grow faster than crowded ones, the leader and shoots answer their light, deaths carry their cause, and the
// stand's sky is the standard overcast one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "architecture/light_growth.hpp"
#include "light/celestial_sphere.hpp"
#include "light/reference_light_solver.hpp"
#include "scenario/scenario.hpp"
#include "stand/establishment.hpp"
#include "stand/mortality.hpp"
#include "stand/production_sky.hpp"
#include "stand/snapshot.hpp"
#include "stand/stand.hpp"
#include "stand/stand_year.hpp"

namespace heliostand {
namespace {

constexpr std::uint64_t growth_seed = 7;

// Every tree of the tiny example stand (8 records with height, DBH, crown radius and crown base) starts with the
// record's values within 2 %.
TEST(Establishment, EveryTreeStartsAsSurveyed) {
  const Scenario scenario = load_scenario(std::filesystem::path(HELIOSTAND_SOURCE_DIR) / "stands/tiny/scenario.toml");
  EstablishmentReport report;
  const std::vector<StandTree> trees = establish_stand(scenario, report);
  ASSERT_EQ(trees.size(), scenario.survey.trees.size());
  for (std::size_t i = 0; i < trees.size(); ++i) {
    const SurveyRecord& record = scenario.survey.trees[i];
    const ConiferTree& tree = trees[i].conifer;
    EXPECT_NEAR(tree.height_m(), record.height_m, 0.02 * record.height_m) << record.id;
    EXPECT_NEAR(tree.dbh_cm(), record.dbh_cm, 0.02 * record.dbh_cm) << record.id;
    EXPECT_NEAR(tree.crown_radius_m(), record.crown_radius_m, 0.02 * record.crown_radius_m) << record.id;
    EXPECT_NEAR(tree.crown_base_m(), record.crown_base_m, 0.02 * record.crown_base_m) << record.id;
    EXPECT_TRUE(tree.light_driven_crown());
  }
}

TEST(GrowthResponse, IsZeroBelowTheCompensationPointLinearThenSaturated) {
  EXPECT_EQ(light_response(0.02, 0.05, 0.5), 0.0);
  EXPECT_NEAR(light_response(0.275, 0.05, 0.5), 0.5, 1e-12);
  EXPECT_EQ(light_response(0.8, 0.05, 0.5), 1.0);
  SpeciesParameters species;
  EXPECT_LT(diameter_response(species, 0.25), diameter_response(species, 0.5));
  EXPECT_NEAR(diameter_response(species, 1.0), 1.0, 1e-12);
}

TEST(GrowthResponse, ShadedShootsAndLeadersGrowLessThanLitOnes) {
  SpeciesParameters species;
  auto grown = [&](double relative_light) {
    ConiferTree tree(species, TreeCalibration{}, {0, 0, 0}, growth_seed, 0);
    tree.grow_to_age(12);
    const double height = tree.height_m();
    std::vector<ConiferTree::FoliageLight> light(tree.leaf_balls().size(), {1.0, relative_light, {0, 0, 1}});
    tree.set_foliage_light(light);
    tree.grow_year();
    double branch_growth = 0;
    for (int s : tree.new_shoot_indices())
      if (tree.shoots()[s].order == 1) branch_growth += glm::length(tree.shoots()[s].tip - tree.shoots()[s].base);
    return std::pair{tree.height_m() - height, branch_growth};
  };
  const auto [lit_height, lit_branches] = grown(1.0);
  const auto [shaded_height, shaded_branches] = grown(0.2);
  const auto [dark_height, dark_branches] = grown(0.01);
  EXPECT_GT(lit_height, 0.0);
  EXPECT_NEAR(shaded_height, lit_height * height_response(species, 0.2), 1e-9);
  EXPECT_EQ(dark_height, 0.0);
  EXPECT_LT(shaded_branches, 0.8 * lit_branches);
  EXPECT_LT(dark_branches, 0.3 * lit_branches);  // only this year's whorl flushes (from the leader)
}

LightParameters finer_sky() { return testing::production_sky(8, 16); }

StandTree planted(int id, glm::dvec3 position, int age) {
  ConiferTree tree(SpeciesParameters{}, TreeCalibration{}, position, growth_seed, id);
  tree.grow_to_age(age);
  tree.set_light_driven_crown(true);
  return StandTree{id, std::to_string(id), "todomatsu", std::move(tree)};
}

// A 4 x 4 block of 14-year trees 2 m apart (2 500 stems/ha); in the released stand the twelve outer trees are thinned at the
// start. The four centre trees' DBH increment and crown radius after 6 years are compared with the crowded stand.
struct Block {
  double dbh_increment_cm = 0, crown_radius_m = 0, relative_light = 0;
  std::vector<double> height_over_site_curve;  // every living tree's height / its calibrated curve at its age
};
Block grow_block(bool released) {
  std::vector<StandTree> trees;
  std::vector<std::string> thinned;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const int id = 4 * i + j;
      trees.push_back(planted(id, {2.0 * i, 2.0 * j, 0.0}, 14));
      if ((i == 0 || i == 3 || j == 0 || j == 3)) thinned.push_back(std::to_string(id));
    }
  std::vector<ThinningEvent> thinning;
  if (released) thinning.push_back({{14}, ThinningRule{ThinningMethod::ids, thinned, {}, {}}, "release", false});
  Stand stand(0.0064, 14, std::move(trees), std::move(thinning));
  ReferenceLightSolver solver(finer_sky());
  StageClock clock;
  StandYear simulated_year(stand, solver, solver, nullptr, nullptr, {growth_seed, 1.0, 6, 1}, clock);
  std::vector<double> start;
  for (const StandTree& tree : stand.trees()) start.push_back(tree.conifer.dbh_cm());
  for (int year = 0; year <= 6; ++year) simulated_year.run(year);
  Block block;
  for (int id : {5, 6, 9, 10}) {
    const StandTree& tree = stand.trees()[id];
    EXPECT_TRUE(tree.alive()) << id;
    block.dbh_increment_cm += (tree.conifer.dbh_cm() - start[id]) / 4;
    block.crown_radius_m += tree.conifer.crown_radius_m() / 4;
    block.relative_light += tree.light_budget.relative() / 4;
  }
  for (const StandTree& tree : stand.trees())
    if (tree.alive())
      block.height_over_site_curve.push_back(tree.conifer.height_m() / tree.conifer.height_at(tree.conifer.age()));
  return block;
}

TEST(GrowthFromLight, ReleasedTreesThickenFasterAndWidenTheirCrowns) {
  const Block crowded = grow_block(false), released = grow_block(true);
  std::cerr << "centre trees over 6 years: DBH +" << released.dbh_increment_cm << " cm released vs +"
            << crowded.dbh_increment_cm << " cm crowded; crown radius " << released.crown_radius_m << " vs "
            << crowded.crown_radius_m << " m; relative light " << released.relative_light << " vs "
            << crowded.relative_light << "\n";
  EXPECT_GT(released.relative_light, crowded.relative_light);
  EXPECT_GT(released.dbh_increment_cm, 1.15 * crowded.dbh_increment_cm);
  EXPECT_GT(released.crown_radius_m, crowded.crown_radius_m);
}

// The leader follows the site curve times its light response: the dominant trees of the crowded block (the tallest
// quarter) stay within 5 % of their calibrated curve after 6 years; a suppressed tree's falling behind is checked in
// LightResponseStand.SuppressedTreeInADenseGroupFallsBehindButNotInTheOpen.
TEST(GrowthFromLight, DominantTreesStayOnTheirSiteCurve) {
  Block crowded = grow_block(false);
  auto& ratios = crowded.height_over_site_curve;
  ASSERT_EQ(ratios.size(), 16u);
  std::sort(ratios.begin(), ratios.end());
  std::cerr << "height / site curve after 6 years: lowest " << ratios.front() << ", highest " << ratios.back() << "\n";
  for (std::size_t k = 12; k < 16; ++k) EXPECT_NEAR(ratios[k], 1.0, 0.05) << k;
}

TEST(GrowthFromLight, ATreeAloneHasRelativeLightOne) {
  std::vector<StandTree> trees;
  trees.push_back(planted(0, {0, 0, 0}, 10));
  Stand stand(0.01, 10, std::move(trees), {});
  ReferenceLightSolver solver(finer_sky());
  stand.illuminate(solver, solver);
  EXPECT_NEAR(stand.trees()[0].light_budget.relative(), 1.0, 1e-9);
  EXPECT_GT(stand.trees()[0].light_budget.absorbed, 0.0);
  // A dimmer stand sky lowers the relative light of every ball: sky_scale reaches growth and shoot death.
  stand.illuminate(solver, solver, 0.5);
  EXPECT_NEAR(stand.trees()[0].light_budget.relative(), 0.5, 1e-9);
  for (const auto& light : stand.trees()[0].conifer.foliage_light()) EXPECT_LE(light.relative_light, 0.5 + 1e-12);
}

TEST(GrowthFromLight, TheSnapshotCarriesEachBallsRelativeLight) {
  std::vector<StandTree> trees;
  trees.push_back(planted(0, {0, 0, 0}, 10));
  trees.push_back(planted(1, {1.5, 0, 0}, 10));
  Stand stand(0.01, 10, std::move(trees), {});
  ReferenceLightSolver solver(finer_sky());
  stand.illuminate(solver, solver);
  const TreeSnapshot snapshot = snapshot_of(stand.trees()[0]);
  const auto& foliage = stand.trees()[0].conifer.foliage_light();
  ASSERT_EQ(snapshot.leaf_ball_relative_light.size(), snapshot.leaf_balls.size());
  ASSERT_EQ(foliage.size(), snapshot.leaf_balls.size());
  bool shaded = false;
  for (std::size_t k = 0; k < foliage.size(); ++k) {
    EXPECT_DOUBLE_EQ(snapshot.leaf_ball_relative_light[k], foliage[k].relative_light) << k;
    shaded = shaded || foliage[k].relative_light < 0.99;
  }
  // The neighbour 1.5 m away shades some ball: the comparison is not of ones, which any copy would pass.
  EXPECT_TRUE(shaded);
}

TEST(Mortality, SuppressionRisesAsRadialGrowthFalls) {
  SpeciesParameters species;
  EXPECT_GT(suppression_probability(species, 0.1), suppression_probability(species, 0.5));
  EXPECT_GT(suppression_probability(species, 0.5), suppression_probability(species, 2.0));
  EXPECT_LT(suppression_probability(species, 2.0), 0.001);
  EXPECT_NEAR(suppression_probability(species, 0.0), 1.0 - std::exp(-species.suppression_m1), 1e-12);
}

// Crowding: above the density limit the least-growing trees die, and only as many as bring the stand back under it.
TEST(Mortality, CrowdingTakesTheLeastGrowingTreesUntilTheStandIsUnderItsLimit) {
  // Four 25.4-cm trees on 0.001 ha at a limit of 2 000 stems/ha: relative density 4 / 2 = 2, so two must die.
  std::vector<CrowdingCandidate> trees{{25.4, 2000.0, 1.5}, {25.4, 2000.0, 0.2}, {25.4, 2000.0, 3.0},
                                       {25.4, 2000.0, 0.4}};
  EXPECT_NEAR(relative_density(trees, 0.001), 2.0, 1e-12);
  EXPECT_EQ(select_crowding_deaths(trees, 0.001), (std::vector<std::size_t>{1, 3}));
  // Under the limit nobody dies; trees below breast height (DBH 0) are no part of the density.
  EXPECT_TRUE(select_crowding_deaths(trees, 0.002).empty());
  trees.push_back({0.0, 2000.0, 0.0});
  EXPECT_EQ(select_crowding_deaths(trees, 0.001), (std::vector<std::size_t>{1, 3}));
}

TEST(Mortality, BackgroundRateKillsAboutItsShare) {
  SpeciesParameters species;
  species.background_mortality = 0.1;
  species.suppression_m1 = 0.0;
  int died = 0;
  for (int id = 0; id < 400; ++id) {
    ConiferTree tree(species, TreeCalibration{}, {0, 0, 0}, growth_seed, id);
    tree.grow_to_age(3);
    if (auto cause = draw_mortality(tree, growth_seed)) {
      EXPECT_EQ(*cause, DeathCause::background);
      ++died;
    }
  }
  EXPECT_NEAR(died / 400.0, 0.1, 0.04);
}

// The standard overcast sky with a forest-floor albedo of 0.15: about 15 % of the light comes from below the
// horizon (seed 000's two-level sky: 40 %), and the zenith is three times as bright as the horizon.
TEST(Sky, StandardOvercastSendsLittleLightFromBelow) {
  LightParameters light;
  light.sky_bands = 32;
  light.sky_sectors = 32;
  auto below_share = [](const LightParameters& p) {
    const CelestialSphere sky(p);
    double below = 0;
    for (const SkyPatch& patch : sky.patches())
      if (patch.direction.z < 0) below += patch.initial_intensity * patch.solid_angle;
    return below / sky.unshaded_total();
  };
  EXPECT_NEAR(below_share(light), 0.4, 0.01);
  light.sky = LightParameters::Sky::standard_overcast;
  EXPECT_NEAR(below_share(light), 0.149, 0.01);  // 2π ρ 7/9 / (4π/3 + 2π ρ 7/9)
  EXPECT_NEAR(light.sky_radiance(0.0), 3.0 * light.sky_radiance(M_PI / 2), 1e-12);
}

}  // namespace
}  // namespace heliostand
