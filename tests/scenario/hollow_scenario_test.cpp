// Scenario [[hollow]] tables and the habitat-tree protection of thinnings (docs/formats.md): hollows join
// their survey records, impossible ones are errors naming the tree and the key, and a marking list may not
// name a protected habitat tree by accident.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "scenario/scenario.hpp"
#include "scenario/scenario_test_files.hpp"

namespace heliostand {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using testing::input_problems;
using testing::minimal_stand;
using testing::write_scenario;

using testing::scenario_problems;

TEST(ScenarioHollows, HollowJoinsItsSurveyRecord) {
  const auto file = write_scenario("hollow_good", minimal_stand +
                                                      "[[hollow]]\n"
                                                      "tree = 2\n"
                                                      "height_m = 1.5\n"
                                                      "azimuth_deg = 180\n"
                                                      "width_m = 0.1\n"
                                                      "polygon_corners = 12\n"
                                                      "seed = 7\n"
                                                      "placement = \"tangent_plane\"\n");
  const Scenario scenario = load_scenario(file);
  ASSERT_EQ(scenario.survey.trees.size(), 4u);
  EXPECT_TRUE(scenario.survey.trees[0].hollows.empty());
  ASSERT_EQ(scenario.survey.trees[1].hollows.size(), 1u);
  const TreeHollow& hollow = scenario.survey.trees[1].hollows[0];
  EXPECT_DOUBLE_EQ(hollow.spec.height_m, 1.5);
  EXPECT_DOUBLE_EQ(hollow.spec.azimuth_deg, 180);
  EXPECT_DOUBLE_EQ(hollow.spec.width_m, 0.1);
  EXPECT_EQ(hollow.spec.polygon_corners, 12);
  EXPECT_EQ(hollow.spec.seed, 7u);
  EXPECT_EQ(hollow.spec.placement, hollow::Placement::tangent_plane);
  EXPECT_TRUE(hollow.seed_given);
  EXPECT_EQ(hollow.line, 11);
  EXPECT_EQ(hollow.field, "hollow[1]");
}

TEST(ScenarioHollows, BadHollowsNameTheTreeAndTheKey) {
  // Tree "2" is 10 m tall, stem radius ≈ 8.6 cm at 1.5 m: 0.6 m is too wide, 9.7 m above 95 % of its height.
  EXPECT_THAT(scenario_problems("hollow_bad", minimal_stand +
                                            "[[hollow]]\n"       // 11
                                            "tree = \"9\"\n"     // 12
                                            "height_m = 1.5\n"
                                            "azimuth_deg = 0\n"
                                            "[[hollow]]\n"       // 15
                                            "tree = 2\n"
                                            "height_m = 1.5\n"
                                            "[[hollow]]\n"       // 18
                                            "tree = 2\n"
                                            "height_m = 1.5\n"
                                            "azimuth_deg = 0\n"
                                            "width_m = 0.6\n"
                                            "[[hollow]]\n"       // 23
                                            "tree = 3\n"
                                            "height_m = 7.9\n"
                                            "azimuth_deg = 0\n"
                                            "placement = \"spiral\"\n"),
              ElementsAre("scenario.toml:15: key 'hollow[2].azimuth_deg': required key missing",
                          "scenario.toml:27: key 'hollow[4].placement': expected \"cylindrical\" or \"tangent_plane\", "
                          "got \"spiral\"",
                          "scenario.toml:12: key 'hollow[1].tree': tree id \"9\" is not in the survey",
                          HasSubstr("scenario.toml:18: key 'hollow[3].width_m': tree \"2\": 0.6 m is too wide"),
                          HasSubstr("scenario.toml:23: key 'hollow[4].height_m': tree \"3\": the hollow reaches")));
}

TEST(ScenarioHollows, ASurveyHollowClashingWithAScenarioHollowIsReportedOnTheHigherOne) {
  // Tree "1" has a hollow at 1.6 m from the survey column; the scenario adds one at 1.4 m on the same tree.
  // Each fits alone, but their bark patches overlap: the higher one, the survey's, carries the problem.
  const std::string survey = "id,x,y,height,dbh,crown_radius,crown_base,hollow\n"
                             "1,2,2,9,12,1,4,1.6/0\n"
                             "2,7,2,10,13,1.1,4.2,\n"
                             "3,2,7,8,11,0.9,3.8,\n"
                             "4,7,7,9.5,12.5,1,4,\n";
  const auto lines = scenario_problems("hollow_clash", minimal_stand +
                                                           "[[hollow]]\n"  // 11
                                                           "tree = 1\n"
                                                           "height_m = 1.4\n"
                                                           "azimuth_deg = 180\n",
                                       survey);
  ASSERT_EQ(lines.size(), 1u) << ::testing::PrintToString(lines);
  EXPECT_THAT(lines[0], HasSubstr("survey.csv:2: column 'hollow': tree \"1\", hollow 1: height_m: its bark patch"));
  EXPECT_THAT(lines[0], HasSubstr("of hollow[1] at 1.4 m"));
}

const std::string habitat_tree_3 =
    "[[hollow]]\n"
    "tree = 3\n"
    "height_m = 1.3\n"
    "azimuth_deg = 90\n";

TEST(ScenarioHollows, MarkingListNamingAProtectedHabitatTreeIsAnError) {
  EXPECT_THAT(scenario_problems("hollow_marked", minimal_stand + habitat_tree_3 +
                                               "[[thinning]]\n"
                                               "age = 25\n"
                                               "method = \"ids\"\n"
                                               "ids = [1, 3]\n"),
              ElementsAre("scenario.toml:18: key 'thinning[1].ids': tree id \"3\" carries a hollow (a habitat tree, "
                          "protected from thinning); set protect_habitat_trees = false in this thinning to remove it"));
  const auto file = write_scenario("hollow_marked_on_purpose", minimal_stand + habitat_tree_3 +
                                                                   "[[thinning]]\n"
                                                                   "age = 25\n"
                                                                   "method = \"ids\"\n"
                                                                   "ids = [1, 3]\n"
                                                                   "protect_habitat_trees = false\n");
  const Scenario scenario = load_scenario(file);
  ASSERT_EQ(scenario.thinning.size(), 1u);
  EXPECT_FALSE(scenario.thinning[0].protect_habitat_trees);
}

}  // namespace
}  // namespace heliostand
