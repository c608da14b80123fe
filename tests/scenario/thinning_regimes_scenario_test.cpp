// The [[thinning]] regimes and triggers in a scenario: each key read into the event, and each bad key or value
// reported with the file, line, key and reason.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "scenario/scenario.hpp"
#include "scenario/scenario_test_files.hpp"

namespace heliostand {
namespace {

using testing::minimal_stand;
using testing::scenario_problems;
using testing::write_scenario;
using ::testing::ElementsAre;
using Measure = StandCondition::Measure;

using testing::stands;

TEST(ThinningRegimesScenario, EveryRegimeAndTriggerIsRead) {
  const auto file = write_scenario("regimes", minimal_stand +
                                                  "[competition]\n"
                                                  "hegyi_radius_m = 5\n"
                                                  "[[thinning]]\n"
                                                  "when_basal_area_exceeds_m2_per_ha = 40\n"
                                                  "repeat = true\n"
                                                  "method = \"neutral\"\n"
                                                  "remove_basal_area_fraction = 0.3\n"
                                                  "[[thinning]]\n"
                                                  "age = 25\n"
                                                  "method = \"crop_tree\"\n"
                                                  "crop_trees_per_ha = 200\n"
                                                  "crop_tree_spacing_m = 4\n"
                                                  "competitors_per_crop_tree = 2\n"
                                                  "[[thinning]]\n"
                                                  "when_top_height_reaches_m = 12\n"
                                                  "repeat_every_years = 3\n"
                                                  "method = \"dbh_class\"\n"
                                                  "dbh_max_cm = 12\n"
                                                  "remove_fraction = 0.5\n"
                                                  "[[thinning]]\n"
                                                  "age = 22\n"
                                                  "method = \"rows\"\n"
                                                  "row_interval = 2\n"
                                                  "row_azimuth_deg = 0\n");
  const Scenario s = load_scenario(file);
  EXPECT_EQ(s.competition.hegyi_radius_m, 5.0);
  ASSERT_EQ(s.thinning.size(), 4u);
  // Fixed ages first, by age; then the triggered events in file order. scenario_order keeps the file's order.
  const ThinningEvent& rows = s.thinning[0];
  EXPECT_EQ(rows.rule.method, ThinningMethod::rows);
  EXPECT_EQ(rows.when.stand_age, 22);
  EXPECT_EQ(rows.scenario_order, 3);
  EXPECT_EQ(rows.rule.rows.interval, 2);
  EXPECT_EQ(rows.rule.rows.first_row, 1);
  EXPECT_EQ(rows.rule.rows.azimuth_deg, 0.0);
  EXPECT_EQ(rows.rule.rows.tolerance_m, 1.0);
  EXPECT_FALSE(rows.when.repeat_every_years);

  const ThinningEvent& crop = s.thinning[1];
  EXPECT_EQ(crop.rule.method, ThinningMethod::crop_tree);
  EXPECT_EQ(crop.scenario_order, 1);
  EXPECT_EQ(crop.rule.crop_trees.crop_trees_per_ha, 200.0);
  EXPECT_EQ(crop.rule.crop_trees.spacing_m, 4.0);
  EXPECT_EQ(crop.rule.crop_trees.competitor_radius_m, 5.0);  // the [competition] radius
  EXPECT_EQ(crop.rule.crop_trees.competitors_per_crop_tree, 2);

  const ThinningEvent& neutral = s.thinning[2];
  EXPECT_EQ(neutral.rule.method, ThinningMethod::neutral);
  EXPECT_EQ(neutral.scenario_order, 0);
  EXPECT_FALSE(neutral.when.at_fixed_age());
  ASSERT_TRUE(neutral.when.condition);
  EXPECT_EQ(neutral.when.condition->measure, Measure::basal_area_m2_per_ha);
  EXPECT_EQ(neutral.when.condition->threshold, 40.0);
  EXPECT_EQ(neutral.when.repeat_every_years, 5);  // repeat = true: the default interval
  EXPECT_EQ(neutral.rule.remove_basal_area_fraction, 0.3);

  const ThinningEvent& by_class = s.thinning[3];
  EXPECT_EQ(by_class.rule.method, ThinningMethod::dbh_class);
  EXPECT_EQ(by_class.when.condition->measure, Measure::top_height_m);
  EXPECT_EQ(by_class.when.condition->threshold, 12.0);
  EXPECT_EQ(by_class.when.repeat_every_years, 3);
  EXPECT_EQ(by_class.rule.dbh_class.min_cm, 0.0);
  EXPECT_EQ(by_class.rule.dbh_class.max_cm, 12.0);
  EXPECT_EQ(by_class.rule.remove_fraction, 0.5);
}

TEST(ThinningRegimesScenario, TriggeredEventsAreNotBoundToTheRunsAges) {
  // A triggered stems target above today's density is no error (when it fires is not known; met, it removes
  // nothing), and a shorter run never cuts a triggered event off.
  Scenario s = load_scenario(write_scenario("triggered", minimal_stand +
                                                             "[[thinning]]\n"
                                                             "when_top_height_reaches_m = 30\n"
                                                             "method = \"from_below\"\n"
                                                             "target_stems_per_ha = 500\n"));
  s.set_years(1);
  EXPECT_EQ(s.run.years, 1);
}

TEST(ThinningRegimesScenario, BadRegimeKeys) {
  EXPECT_THAT(scenario_problems("regime_keys", minimal_stand +
                                                   "[[thinning]]\n"                   // 11
                                                   "age = 25\n"
                                                   "method = \"rows\"\n"              // 13
                                                   "row_interval = 1\n"               // 14
                                                   "[[thinning]]\n"                   // 15
                                                   "age = 25\n"
                                                   "method = \"crop_tree\"\n"
                                                   "competitors_per_crop_tree = 0\n"  // 18
                                                   "target_stems_per_ha = 300\n"      // 19
                                                   "[[thinning]]\n"                   // 20
                                                   "age = 25\n"
                                                   "method = \"dbh_class\"\n"
                                                   "[[thinning]]\n"                   // 23
                                                   "age = 25\n"
                                                   "method = \"dbh_class\"\n"
                                                   "dbh_min_cm = 20\n"
                                                   "dbh_max_cm = 10\n"                // 27
                                                   "[[thinning]]\n"                   // 28
                                                   "age = 25\n"
                                                   "method = \"neutral\"\n"
                                                   "remove_fraction = 1.5\n"),        // 31
              ElementsAre("scenario.toml:14: key 'thinning[1].row_interval': expected an integer in [2, 1000], got 1",
                          "scenario.toml:18: key 'thinning[2].competitors_per_crop_tree': expected an integer in [1, "
                          "1000], got 0",
                          "scenario.toml:15: key 'thinning[2].crop_trees_per_ha': required key missing (method "
                          "\"crop_tree\" needs how many crop trees per ha)",
                          "scenario.toml:15: key 'thinning[2].crop_tree_spacing_m': required key missing (method "
                          "\"crop_tree\" needs the least distance between two crop trees)",
                          "scenario.toml:19: key 'thinning[2].target_stems_per_ha': not used by method \"crop_tree\" "
                          "(it chooses crop trees and removes their competitors)",
                          "scenario.toml:20: key 'thinning[3].dbh_min_cm': required key missing (method \"dbh_class\" "
                          "needs the class: dbh_min_cm, dbh_max_cm or both)",
                          "scenario.toml:27: key 'thinning[4].dbh_max_cm': must be greater than dbh_min_cm (20), got 10",
                          "scenario.toml:31: key 'thinning[5].remove_fraction': expected a number in (0, 1], got 1.5",
                          // After the survey is read: the four surveyed trees stand on a square, no row direction.
                          "scenario.toml:13: key 'thinning[1].method': method \"rows\" finds no planting rows in the "
                          "survey's positions: no row direction: the trees' nearest neighbours point along several "
                          "directions (agreement 0.00, at least 0.5 needed; a square planting?); give "
                          "row_azimuth_deg"));
}

TEST(ThinningRegimesScenario, BadTriggerAndCompetitionKeys) {
  EXPECT_THAT(scenario_problems("trigger_keys", minimal_stand +
                                                    "[[thinning]]\n"                            // 11
                                                    "age = 25\n"
                                                    "when_top_height_reaches_m = 12\n"          // 13
                                                    "method = \"from_below\"\n"
                                                    "remove_fraction = 0.2\n"
                                                    "[[thinning]]\n"                            // 16
                                                    "when_basal_area_exceeds_m2_per_ha = 0\n"   // 17
                                                    "repeat = false\n"
                                                    "repeat_every_years = 3\n"                  // 19
                                                    "method = \"from_below\"\n"
                                                    "target_stems_per_ha = 500\n"
                                                    "[[thinning]]\n"                            // 22
                                                    "method = \"from_above\"\n"
                                                    "remove_fraction = 0.2\n"
                                                    "repeat = \"yes\"\n"                        // 25
                                                    "[competition]\n"
                                                    "hegyi_radius_m = 0\n"                      // 27
                                                    "radius = 3\n"),                            // 28
              ElementsAre("scenario.toml:27: key 'competition.hegyi_radius_m': expected a number in (0, 100], got 0",
                          "scenario.toml:28: key 'competition.radius': unknown key (known keys here: hegyi_radius_m)",
                          "scenario.toml:13: key 'thinning[1].when_top_height_reaches_m': a thinning happens at an age "
                          "or on one condition: give one of age, when_basal_area_exceeds_m2_per_ha and "
                          "when_top_height_reaches_m, got age and when_top_height_reaches_m",
                          "scenario.toml:17: key 'thinning[2].when_basal_area_exceeds_m2_per_ha': expected a number "
                          "in (0, 10000], got 0",
                          "scenario.toml:19: key 'thinning[2].repeat_every_years': not used with repeat = false "
                          "(remove one of the two)",
                          "scenario.toml:22: key 'thinning[3].age': required key missing (or, instead of a fixed age, "
                          "a condition: when_basal_area_exceeds_m2_per_ha or when_top_height_reaches_m)",
                          "scenario.toml:25: key 'thinning[3].repeat': expected true or false, got a string"));
}

TEST(ThinningRegimesScenario, RowsAndCropTreesAreCheckedAgainstTheSurvey) {
  EXPECT_THAT(scenario_problems("regimes_vs_survey", minimal_stand +
                                                         "[[thinning]]\n"            // 11
                                                         "age = 25\n"
                                                         "method = \"rows\"\n"
                                                         "row_interval = 2\n"
                                                         "row_azimuth_deg = 0\n"
                                                         "first_row = 3\n"           // 16
                                                         "[[thinning]]\n"            // 17
                                                         "age = 26\n"
                                                         "method = \"crop_tree\"\n"
                                                         "crop_trees_per_ha = 50\n"  // 20
                                                         "crop_tree_spacing_m = 3\n"),
              ElementsAre("scenario.toml:16: key 'thinning[1].first_row': row 3 is beyond the last of the survey's 2 "
                          "planting rows (along 0.0°)",
                          "scenario.toml:20: key 'thinning[2].crop_trees_per_ha': 50 crop trees/ha on 0.01 ha is less "
                          "than one crop tree (floor of 0.50)"));
}

}  // namespace
}  // namespace heliostand
