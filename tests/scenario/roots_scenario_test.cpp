// [roots], [roots.SPECIES(.TYPE)], [soil], [coupling], [[root_pruning]]: values reach the settings, bad
// values are InputErrors naming line and key path.
#include <algorithm>

#include <gtest/gtest.h>

#include "scenario/scenario.hpp"
#include "scenario/scenario_test_files.hpp"

namespace heliostand {
namespace {

using testing::input_problems;
using testing::minimal_stand;
using testing::write_scenario;

using testing::scenario_problems;

TEST(RootsScenario, DefaultsWhenNoTables) {
  const Scenario s = load_scenario(write_scenario("roots_defaults", minimal_stand));
  EXPECT_TRUE(s.roots.enabled);
  EXPECT_TRUE(s.roots.by_species.empty());
  EXPECT_EQ(s.roots.parameters_of("todomatsu").of(roots::RootType::lateral).elongation_m_per_year,
            roots::tap_rooted_conifer().of(roots::RootType::lateral).elongation_m_per_year);
  EXPECT_DOUBLE_EQ(s.roots.soil.spacing_m, 0.5);
  EXPECT_EQ(s.roots.soil.moisture.kind, SoilFieldSetting::Kind::uniform);
  EXPECT_DOUBLE_EQ(s.roots.coupling.alpha_b, 0.5);
  EXPECT_TRUE(s.roots.pruning.empty());
}

TEST(RootsScenario, EveryTableReachesTheSettings) {
  const Scenario s = load_scenario(write_scenario("roots_all", minimal_stand +
      "[roots]\nenabled = false\n"
      "[roots.todomatsu]\nmax_woody_order = 2\nuptake_rate_per_m = 0.1\n"
      "[roots.todomatsu.lateral]\nelongation_m_per_year = 0.3\nbranching_to_fine = 2.0\n"
      "alpha = 0.4\nbeta = 0.1\ngamma = 0.4\ndelta = 0.05\nepsilon = 0.05\n"
      "branching_angle_min_deg = 70\nbranching_angle_max_deg = 80\n"
      "[soil]\nspacing_m = 0.25\ndepth_m = 2\nmoisture = { gradient = \"x\", min_face = 1.0, max_face = 0.2 }\n"
      "nutrient = { layer_bottoms_m = [0.3, 1.0], values = [1.0, 0.5] }\nmoisture_recharge = 0.5\n"
      "[coupling]\nrho = 0.02\ntau = 2\nalpha_b = 0.3\nalpha_r = 0.7\n"
      "[[root_pruning]]\nevery_year = true\nsectors = [6, 7, 0, 1]\nmin_depth_m = 0.1\n"
      "[[root_pruning]]\nage = 25\ntrees = [\"2\", 3]\n"));
  EXPECT_FALSE(s.roots.enabled);
  const roots::RootParameters& p = s.roots.by_species.at("todomatsu");
  EXPECT_EQ(p.max_woody_order, 2);
  EXPECT_DOUBLE_EQ(p.uptake_rate_per_m, 0.1);
  const auto& lateral = p.of(roots::RootType::lateral);
  EXPECT_DOUBLE_EQ(lateral.elongation_m_per_year, 0.3);
  EXPECT_DOUBLE_EQ(lateral.branching_frequency[roots::index_of(roots::RootType::fine)], 2.0);
  EXPECT_DOUBLE_EQ(lateral.tropisms.beta, 0.1);
  EXPECT_DOUBLE_EQ(lateral.branching_angle_deg.min, 70.0);
  EXPECT_DOUBLE_EQ(p.of(roots::RootType::main).elongation_m_per_year,
                   roots::tap_rooted_conifer().of(roots::RootType::main).elongation_m_per_year);
  EXPECT_DOUBLE_EQ(s.roots.soil.spacing_m, 0.25);
  EXPECT_EQ(s.roots.soil.moisture.kind, SoilFieldSetting::Kind::gradient);
  EXPECT_EQ(s.roots.soil.moisture.axis, 0);
  EXPECT_DOUBLE_EQ(s.roots.soil.moisture.at_max, 0.2);
  EXPECT_EQ(s.roots.soil.nutrient.kind, SoilFieldSetting::Kind::layers);
  EXPECT_EQ(s.roots.soil.nutrient.values, (std::vector<double>{1.0, 0.5}));
  EXPECT_DOUBLE_EQ(s.roots.soil.recharge.moisture_rate, 0.5);
  EXPECT_DOUBLE_EQ(s.roots.coupling.rho, 0.02);
  EXPECT_DOUBLE_EQ(s.roots.coupling.alpha_r, 0.7);
  ASSERT_EQ(s.roots.pruning.size(), 2u);
  EXPECT_TRUE(s.roots.pruning[0].every_year);
  EXPECT_EQ(s.roots.pruning[0].sectors, (std::vector<int>{6, 7, 0, 1}));
  EXPECT_DOUBLE_EQ(s.roots.pruning[0].min_depth_m, 0.1);
  EXPECT_EQ(s.roots.pruning[1].stand_age, 25);
  EXPECT_EQ(s.roots.pruning[1].tree_labels, (std::vector<std::string>{"2", "3"}));
}

TEST(RootsScenario, BadValuesNameLineAndKey) {
  std::vector<std::string> got = scenario_problems("roots_bad", minimal_stand +
      "[roots]\nsolver = \"gpu\"\n"                                   // 11, 12
      "[roots.ezomatsu]\n"                                            // 13
      "[roots.todomatsu.lateral]\nalpha = 0.9\nradius_m = -1\n"       // 14, 15, 16
      "[soil]\nspacing_m = 0\nmoisture = 1.5\n"                       // 17, 18, 19
      "nutrient = { gradient = \"w\", min_face = 1, max_face = 0 }\n" // 20
      "[coupling]\nalpha_b = 2\n"                                     // 21, 22
      "[[root_pruning]]\nsectors = [8]\n"                             // 23, 24
      "[[root_pruning]]\nage = 40\nevery_year = true\n");             // 25, 26, 27
  std::vector<std::string> expected{
          "scenario.toml:12: key 'roots.solver': no longer read: run.device (or grow --device) runs the light and "
          "the roots on one backend",
          "scenario.toml:13: key 'roots.ezomatsu': no species \"ezomatsu\" (a [roots.SPECIES] table names a [species] "
          "table, or todomatsu when there is none)",
          "scenario.toml:16: key 'roots.todomatsu.lateral.radius_m': expected a number in (0, 7.5], got -1",
          "scenario.toml:15: key 'roots.todomatsu.lateral.alpha': tropism weights alpha + beta + gamma + delta + "
          "epsilon must sum to 1 (seed 003), got 1.4 (give all five when changing one)",
          "scenario.toml:18: key 'soil.spacing_m': expected a number in [0.05, 5], got 0",
          "scenario.toml:19: key 'soil.moisture': expected a number in [0, 1], got 1.5",
          "scenario.toml:20: key 'soil.nutrient.gradient': expected \"x\", \"y\" or \"z\", got \"w\"",
          "scenario.toml:22: key 'coupling.alpha_b': expected a number in [0, 1], got 2",
          "scenario.toml:23: key 'root_pruning[1]': needs exactly one of age and every_year = true",
          "scenario.toml:24: key 'root_pruning[1].sectors': element 1: expected a path 0..7 (45° sectors "
          "counter-clockwise from east)",
          "scenario.toml:26: key 'root_pruning[2].age': root pruning at age 40 is outside the simulated years (stand "
          "age 21 to 30)",
          "scenario.toml:25: key 'root_pruning[2]': needs exactly one of age and every_year = true"};
  // Order of reporting is by table; compare as sets.
  std::sort(got.begin(), got.end());
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(got, expected);
}

}  // namespace
}  // namespace heliostand
