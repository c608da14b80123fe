// Each physical limit of a survey value is an error before anything runs (issue: a 1e308-m tree crashed grow),
// with the file, line, column and the fact behind the limit; a slenderness outside the plausible range warns.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "survey/plausible_limits.hpp"
#include "survey/read_survey.hpp"
#include "survey/survey_test_files.hpp"

namespace heliostand {
namespace {

using testing::input_problems;
using testing::write_test_file;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

std::vector<std::string> limit_problems(const std::string& text) {
  return testing::survey_problems("limits.csv", text, testing::stand_of_age());
}

TEST(PlausibleLimits, EachColumnsLimitIsAnErrorJustAboveIt) {
  struct Case {
    std::string column;
    std::string row;  // x,y,height,dbh,<column>
    std::string limit;
  };
  const std::vector<Case> cases{
      {"x", "1.0001e7,1,15,20", "1e+07 m"},     {"y", "1,-1.0001e7,15,20", "1e+07 m"},
      {"height", "1,1,130.01,20", "130 m"},      {"dbh", "1,1,15,1500.1", "1500 cm"},
  };
  for (const Case& c : cases) {
    const auto lines = limit_problems("x,y,height,dbh\n" + c.row + "\n");
    ASSERT_EQ(lines.size(), 1u) << c.column;
    EXPECT_THAT(lines[0], HasSubstr("s.csv:2: column '" + c.column + "'")) << c.column;
    EXPECT_THAT(lines[0], HasSubstr("beyond the plausible limit of " + c.limit)) << c.column;
  }
  const std::vector<std::pair<std::string, std::string>> extra{
      {"crown_radius", "30.5"}, {"crown_diameter", "61"}, {"crown_base", "131"}, {"age", "5001"},
      {"crown_ratio", "45"}};
  for (const auto& [column, value] : extra) {
    const auto lines = limit_problems("x,y,height,dbh," + column + "\n1,1,15,20," + value + "\n");
    ASSERT_FALSE(lines.empty()) << column;
    EXPECT_THAT(lines[0], HasSubstr("s.csv:2: column '" + column + "': " + value)) << column;
    EXPECT_THAT(lines[0], HasSubstr("beyond the plausible limit")) << column;
  }
}

TEST(PlausibleLimits, ValuesAtTheLimitsPass) {
  const SurveyReadOptions options = testing::stand_of_age();
  const Survey survey =
      read_survey(write_test_file("limits_ok.csv", "x,y,height,dbh,crown_radius,age\n1e7,-1e7,130,1500,30,5000\n"),
                  options);
  ASSERT_EQ(survey.trees.size(), 1u);
  EXPECT_DOUBLE_EQ(survey.trees[0].height_m, 130.0);
}

TEST(PlausibleLimits, TheCrashingHeightOfTheIssueIsRefused) {
  EXPECT_THAT(limit_problems("x,y,height\n1,1,1e308\n"),
              ElementsAre("s.csv:2: column 'height': 1e+308 m is beyond the plausible limit of 130 m (the tallest "
                          "measured tree, a coast redwood, is 116 m)"));
}

TEST(PlausibleLimits, TheLimitAppliesAfterUnitConversion) {
  // 13,000 cm is 130 m (allowed); 1,300 ft is 396 m (refused).
  const SurveyReadOptions options = testing::stand_of_age();
  const Survey survey = read_survey(write_test_file("limits_cm.csv", "x,y,height_cm\n1,1,13000\n"), options);
  EXPECT_DOUBLE_EQ(survey.trees[0].height_m, 130.0);
  EXPECT_THAT(limit_problems("x,y,height_ft\n1,1,1300\n"),
              ElementsAre(HasSubstr("column 'height_ft': 396.24 m is beyond the plausible limit of 130 m")));
}

TEST(PlausibleLimits, SlendernessOutsideTheRangeWarns) {
  const SurveyReadOptions options = testing::stand_of_age();
  // 500 m would be an error; 40 m with a 12-cm DBH (ratio 333) is a warning, a 3-m sapling is exempt.
  const Survey survey = read_survey(
      write_test_file("slender.csv", "x,y,height,dbh\n1,1,40,12\n2,2,20,25\n3,3,3,1\n4,4,10,150\n"), options);
  ASSERT_EQ(survey.trees.size(), 4u);
  std::string found;
  for (const auto& warning : survey.warnings)
    if (warning.find("height/DBH ratio") != std::string::npos) found = warning;
  EXPECT_THAT(found, HasSubstr("2 trees taller than 5 m have a height/DBH ratio outside [10, 200] (lines 2, 5)"));
}

}  // namespace
}  // namespace heliostand
