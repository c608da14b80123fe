// Every numeric scenario key has an upper limit (issue 11, "Plausibility"): a value just above it is an error that
// names the file, the key, the value and the limit. The cases are scenario_limit_cases.hpp; a numeric key the
// parsers read without a case fails EveryNumericKeyHasALimitCase, so a new key cannot skip its limit.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <sstream>

#include "scenario/scenario_limit_cases.hpp"
#include "scenario/scenario_test_files.hpp"

namespace heliostand {
namespace {

using ::testing::HasSubstr;
using testing::Bound;
using testing::limit_cases;
using testing::LimitCase;

std::string folder_name(const std::string& key_path) {
  std::string name = "limit_" + key_path;
  std::replace_if(name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
  return name;
}

std::vector<std::string> problems_above(const LimitCase& c) {
  return testing::scenario_problems(folder_name(c.key_path) + "_above",
                                    testing::scenario_text(c, c.above_limit()), testing::limits_survey);
}

// "expected a number in (0, 130]": the message states the limit as the range's upper end.
std::string limit_text(const LimitCase& c) {
  return fmt::format("{:g}{}", c.max, c.bound == Bound::exclusive ? ")" : "]");
}

TEST(ScenarioLimits, AValueJustAboveEachLimitIsAnErrorNamingKeyValueAndLimit) {
  for (const LimitCase& c : limit_cases()) {
    const auto problems = problems_above(c);
    const std::string key = "key '" + c.key_path + "'";
    const auto named = std::find_if(problems.begin(), problems.end(),
                                    [&](const std::string& line) { return line.find(key) != std::string::npos; });
    ASSERT_NE(named, problems.end()) << c.key_path << " = " << c.above_limit() << " was not refused by its key: "
                                     << ::testing::PrintToString(problems);
    EXPECT_THAT(*named, ::testing::StartsWith("scenario.toml:")) << c.key_path;
    EXPECT_THAT(*named, HasSubstr("got " + c.above_limit())) << c.key_path;
    EXPECT_THAT(*named, HasSubstr(limit_text(c))) << c.key_path;
  }
}

TEST(ScenarioLimits, NoValueAtItsLimitIsRefusedByItsOwnRange) {
  // A value at its limit may still break a rule relating it to another key (a leaf ball's least radius above its
  // greatest, a thinning age after the run): that rule is not the limit, and limits_cli_test.cpp sees those exits.
  for (const LimitCase& c : limit_cases()) {
    const auto file = testing::write_scenario(folder_name(c.key_path) + "_at", testing::scenario_text(c, c.at_limit()),
                                              testing::limits_survey);
    try {
      load_scenario(file);
    } catch (const InputError& error) {
      for (const auto& problem : error.problems())
        if (problem.field == c.key_path)
          EXPECT_THAT(problem.reason, ::testing::Not(::testing::StartsWith("expected ")))
              << c.key_path << " = " << c.at_limit();
    }
  }
}

// The keys the parser reads in the table that `toml` writes, from the message about an unknown key added to it
// ("unknown key (known keys here: a, b, c)").
std::set<std::string> known_keys(const std::string& toml, const std::string& probe_path) {
  const auto problems = testing::scenario_problems("limit_known_keys", toml, testing::limits_survey);
  const std::string marker = "known keys here: ";
  for (const auto& line : problems) {
    if (line.find("key '" + probe_path + "'") == std::string::npos) continue;
    const auto from = line.find(marker) + marker.size();
    std::istringstream list(line.substr(from, line.rfind(')') - from));
    std::set<std::string> keys;
    for (std::string key; std::getline(list >> std::ws, key, ',');) keys.insert(key);
    return keys;
  }
  ADD_FAILURE() << "no unknown-key message for " << probe_path << ": " << ::testing::PrintToString(problems);
  return {};
}

TEST(ScenarioLimits, EveryNumericKeyHasALimitCase) {
  struct Table {
    std::string path;  // key path prefix of its keys
    std::string toml;  // the table with the probe key zz_probe = 0
    std::set<std::string> not_numbers;  // strings, booleans, id lists, sub-tables; random seeds (any uint64)
  };
  const std::string stand = testing::stand_table() + "zz_probe = 0\n" + testing::default_run;
  const std::string probe = "zz_probe = 0\n";
  const std::vector<Table> tables{
      {"stand", stand, {"survey", "survey_separator", "multi_stem", "survey_units", "default_species"}},
      {"run", testing::stand_table() + testing::default_run + probe, {"seed", "device", "detail", "vtk_compression"}},
      {"species.todomatsu", testing::stand_table() + testing::default_run + "[species.todomatsu]\n" + probe, {}},
      {"light", testing::stand_table() + testing::default_run + "[light]\n" + probe,
       {"exact", "periodic", "sky", "far_field_bias_correction"}},
      {"competition", testing::stand_table() + testing::default_run + "[competition]\n" + probe, {}},
      {"thinning[1]", testing::stand_table() + testing::default_run + "[[thinning]]\nage = 21\nmethod = \"ids\"\n" +
                          "ids = [\"1\"]\n" + probe,
       {"method", "ids", "repeat", "reason", "protect_habitat_trees"}},
      {"hollow[1]", testing::stand_table() + testing::default_run + "[[hollow]]\ntree = \"1\"\nheight_m = 1\n" +
                        "azimuth_deg = 0\n" + probe,
       {"tree", "placement", "seed"}},
      {"roots.todomatsu", testing::stand_table() + testing::default_run + "[roots.todomatsu]\n" + probe,
       {"main", "lateral", "sinker", "fine"}},
      {"roots.todomatsu.lateral", testing::stand_table() + testing::default_run + "[roots.todomatsu.lateral]\n" + probe,
       {}},
      {"soil", testing::stand_table() + testing::default_run + "[soil]\n" + probe, {"file"}},
      {"soil.moisture", testing::stand_table() + testing::default_run +
                            "[soil]\nmoisture = { gradient = \"z\", min_face = 1, max_face = 1, zz_probe = 0 }\n",
       {"gradient"}},
      {"soil.moisture", testing::stand_table() + testing::default_run +
                            "[soil]\nmoisture = { layer_bottoms_m = [1], values = [1], zz_probe = 0 }\n",
       {}},
      {"coupling", testing::stand_table() + testing::default_run + "[coupling]\n" + probe, {"enabled"}},
      {"root_pruning[1]", testing::stand_table() + testing::default_run + "[[root_pruning]]\nevery_year = true\n" + probe,
       {"every_year", "sectors", "trees"}},
  };
  std::set<std::string> with_case;
  for (const LimitCase& c : limit_cases()) with_case.insert(c.key_path);
  for (const Table& table : tables) {
    for (const std::string& key : known_keys(table.toml, table.path + ".zz_probe")) {
      if (table.not_numbers.count(key)) continue;
      EXPECT_TRUE(with_case.count(table.path + "." + key)) << table.path << "." << key << " has no limit case";
    }
  }
  // The uniform soil levels are numbers too (the table form is checked above).
  EXPECT_TRUE(with_case.count("soil.moisture") && with_case.count("soil.nutrient"));
}

// Rules of what the model can grow that relate keys to each other or to the survey (check_model_limits.cpp).

TEST(ScenarioLimits, EqNineBranchTriangleMustStayOpenAtTheOldestAgeTheRunReaches) {
  // theta = 20° t^beta with d0 = 60°: beta 0.6 closes the triangle at age 21 (124° + 60°); 0.5 leaves it open.
  const std::string stand = testing::stand_table() + testing::default_run;
  EXPECT_THAT(testing::scenario_problems("closure", stand + "[species.todomatsu]\ncrown_angle_beta = 0.6\n",
                                         testing::limits_survey),
              ::testing::ElementsAre(HasSubstr("scenario.toml:11: key 'species.todomatsu.crown_angle_beta': at tree "
                                               "age 21 the crown angle 20 x 21^0.6 = 124.3° and "
                                               "initial_branch_angle_deg 60° leave eq. 9's branch triangle -4.269° "
                                               "open, less than 5°")));
  Scenario scenario = load_scenario(testing::write_scenario(
      "closure_years", stand + "[species.todomatsu]\ncrown_angle_beta = 0.5\n", testing::limits_survey));
  // --years 40 ends at age 60: 20° x 60^0.5 = 155° + 60° closes it.
  EXPECT_THAT(testing::input_problems([&] { scenario.set_years(40); }),
              ::testing::ElementsAre(HasSubstr("key 'run.years': --years 40: species todomatsu: at tree age 60")));
  EXPECT_EQ(scenario.run.years, 1);
  scenario.set_years(10);
  EXPECT_EQ(scenario.run.years, 10);
}

TEST(ScenarioLimits, SurveyedTreesOlderThanTheModelCanGrowAreRefused) {
  const std::string survey = "id,x,y,height,dbh,age\n1,2,2,9,12,100\n2,7,7,9,12,101\n";
  EXPECT_THAT(testing::scenario_problems("old_tree", testing::stand_table() + testing::default_run, survey),
              ::testing::ElementsAre("survey.csv:3: column 'age': 101 years is beyond the 100 years the model can "
                                     "grow a tree to (" + std::string(limit::grown_tree_age.why) + ")"));
}

TEST(ScenarioLimits, TheSoilGridIsBoundedWithoutASoilTable) {
  const std::string wide = testing::stand_table("x_max", "x_max = 1e6\n") + testing::default_run;
  EXPECT_THAT(testing::scenario_problems("wide_plot", wide, testing::limits_survey),
              ::testing::ElementsAre(HasSubstr("scenario.toml: key 'soil.spacing_m': 2.4e+08 voxels of 0.5 m under "
                                               "the 1e+06 m x 10 m plot: too many (at most 5e+07)")));
  // Without roots there is no soil grid to bound.
  EXPECT_NO_THROW(load_scenario(
      testing::write_scenario("wide_plot_no_roots", wide + "[roots]\nenabled = false\n", testing::limits_survey)));
}

TEST(ScenarioLimits, BranchesPerWhorlAreBounded) {
  // a3 x + b3 with x = 0.38: a3 = 61 gives 20.0, a3 = 62 gives 20.4.
  const std::string stand = testing::stand_table() + testing::default_run;
  EXPECT_NO_THROW(load_scenario(testing::write_scenario("whorl_20", stand + "[species.todomatsu]\nwhorl_a3 = 61\n",
                                                        testing::limits_survey)));
  EXPECT_THAT(testing::scenario_problems("whorl_21", stand + "[species.todomatsu]\nwhorl_a3 = 62\n",
                                         testing::limits_survey),
              ::testing::ElementsAre(HasSubstr("key 'species.todomatsu.whorl_b3': first-order branches per whorl a3 "
                                               "x + b3 = 20.372 (eq. 3) must be in [1, 20]")));
}

}  // namespace
}  // namespace heliostand
