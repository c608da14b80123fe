// [stand] keys that say how the survey is laid out (survey_separator, survey_units, multi_stem) and the plot taken
// from the survey's stem positions (plot_margin_m); the overflow guard on every scenario number.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "scenario/scenario.hpp"
#include "scenario/scenario_test_files.hpp"

namespace heliostand {
namespace {

using testing::scenario_problems;
using testing::write_scenario;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

std::string stand_with(const std::string& keys) {
  return "[stand]\nsurvey = \"survey.csv\"\nage_at_survey = 20\n" + keys + "\n[run]\nyears = 10\n";
}

TEST(SurveyFormatScenario, ASemicolonListWithUnitsAndThePlotFromItsTrees) {
  const auto file = write_scenario("european", stand_with("survey_separator = \"semicolon\"\n"
                                                          "survey_units = { dbh = \"mm\" }\n"
                                                          "plot_margin_m = 1.5\n"),
                                   "Nr;X;Y;dbh;h\n1;2,0;2;120;9\n2;7,5;2;131;10\n3;2;7;110;8\n");
  const Scenario scenario = load_scenario(file);
  ASSERT_EQ(scenario.survey.trees.size(), 3u);
  EXPECT_DOUBLE_EQ(scenario.survey.trees[1].x_m, 7.5);
  EXPECT_NEAR(scenario.survey.trees[1].dbh_cm, 13.1, 1e-12);
  EXPECT_DOUBLE_EQ(scenario.stand.plot.x_min, 0.5);
  EXPECT_DOUBLE_EQ(scenario.stand.plot.x_max, 9.0);
  EXPECT_DOUBLE_EQ(scenario.stand.plot.y_min, 0.5);
  EXPECT_DOUBLE_EQ(scenario.stand.plot.y_max, 8.5);
  EXPECT_EQ(scenario.stand.plot_margin_m, 1.5);
}

TEST(SurveyFormatScenario, MultiStemmedTreesMergedWhenTheScenarioSaysSo) {
  const std::string survey = "id,x,y,height,dbh\n1,2,2,9,12\n2,2,2.005,8,9\n3,7,7,9.5,12.5\n";
  EXPECT_THAT(scenario_problems("multi_refuse", stand_with("plot_margin_m = 1"), survey),
              ElementsAre(HasSubstr("survey.csv:3: column 'x,y': stands within 1 cm of the tree on line 2")));
  const Scenario merged = load_scenario(write_scenario("multi_merge", stand_with("plot_margin_m = 1\nmulti_stem = \"merge\""), survey));
  ASSERT_EQ(merged.survey.trees.size(), 2u);
  EXPECT_NEAR(merged.survey.trees[0].dbh_cm, 15.0, 1e-12);
  const Scenario separate =
      load_scenario(write_scenario("multi_separate", stand_with("plot_margin_m = 1\nmulti_stem = \"separate\""), survey));
  EXPECT_EQ(separate.survey.trees.size(), 3u);
}

TEST(SurveyFormatScenario, BadFormatKeysNameTheirLineAndKey) {
  EXPECT_THAT(scenario_problems("bad_format", stand_with("x_min = 0\ny_min = 0\nx_max = 10\ny_max = 10\n"
                                                         "survey_separator = \"pipe\"\n"
                                                         "multi_stem = \"sometimes\"\n"
                                                         "survey_units = { dbh = \"furlong\", colour = \"m\", "
                                                         "height = 3 }\n")),
              ElementsAre("scenario.toml:8: key 'stand.survey_separator': expected \"auto\", \"comma\", \"semicolon\" "
                          "or \"tab\", got \"pipe\"",
                          "scenario.toml:9: key 'stand.multi_stem': expected \"refuse\", \"separate\" or \"merge\", "
                          "got \"sometimes\"",
                          "scenario.toml:10: key 'stand.survey_units.colour': not a survey column with a unit (known: "
                          "x, y, height, dbh, crown_radius, crown_diameter, crown_base, age, crown_ratio)",
                          "scenario.toml:10: key 'stand.survey_units.dbh': 'furlong' is not a unit of dbh (accepted: "
                          "cm, mm, m, dm, in, ft)",
                          "scenario.toml:10: key 'stand.survey_units.height': expected a unit as a string, got an "
                          "integer"));
}

TEST(SurveyFormatScenario, PlotBoundsOrAMarginNotBoth) {
  EXPECT_THAT(scenario_problems("both_plots", stand_with("x_min = 0\ny_min = 0\nx_max = 10\ny_max = 10\n"
                                                         "plot_margin_m = 2\n")),
              ElementsAre("scenario.toml:8: key 'stand.plot_margin_m': give either the plot bounds (x_min, y_min, "
                          "x_max, y_max) or plot_margin_m, not both"));
  EXPECT_THAT(scenario_problems("no_plot", stand_with("")),
              ElementsAre(HasSubstr("key 'stand.x_min': required key missing"), HasSubstr("stand.y_min"),
                          HasSubstr("stand.x_max"), HasSubstr("stand.y_max")));
  EXPECT_THAT(scenario_problems("one_tree_no_margin", stand_with("plot_margin_m = 0"), "x,y,h\n1,1,9\n"),
              ElementsAre(HasSubstr("key 'stand.plot_margin_m': the trees stand on a line or a point")));
}

TEST(SurveyFormatScenario, NumbersBeyondAnyQuantityOfTheModelAreRefused) {
  // The overflow: a site asymptote of 1e308 m would grow a tree of 1e308 m. Each key's own limit refuses it
  // (scenario/scenario_limits.hpp), before the blanket guard (largest_scenario_number) would.
  EXPECT_THAT(scenario_problems("huge_number", testing::minimal_stand + "\n[species.todomatsu]\nsite_asymptote_m = 1e308\n"),
              ElementsAre("scenario.toml:13: key 'species.todomatsu.site_asymptote_m': expected a number in (0, 130], "
                          "got 1e+308 (the tallest measured tree, a coast redwood, is 116 m)"));
  EXPECT_THAT(scenario_problems("huge_years", "[stand]\nsurvey = \"survey.csv\"\nage_at_survey = 20\nx_min = 0\n"
                                              "y_min = 0\nx_max = 10\ny_max = 10\n[run]\nyears = 2000000000\n"),
              ElementsAre(HasSubstr("key 'run.years': expected an integer in [1, 5000], got 2000000000")));
  // A seed is any unsigned number.
  EXPECT_EQ(load_scenario(write_scenario("big_seed", testing::minimal_stand + "seed = 9000000000000000000\n")).run.seed,
            9000000000000000000u);
}

}  // namespace
}  // namespace heliostand
