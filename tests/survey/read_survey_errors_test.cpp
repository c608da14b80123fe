// Every kind of bad survey input, each checked for file, line, column and reason.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "survey/read_survey.hpp"
#include "survey/survey_test_files.hpp"

namespace heliostand {
namespace {

using testing::input_problems;
using testing::write_test_file;
using ::testing::ElementsAre;

using testing::plot_30x30;

std::vector<std::string> problems_of(const std::string& text, SurveyReadOptions options = plot_30x30()) {
  return testing::survey_problems("bad.csv", text, options);
}

TEST(ReadSurveyErrors, UnreadableFile) {
  const auto lines = input_problems([] { read_survey("/nonexistent/heliostand/survey.csv"); });
  EXPECT_THAT(lines, ElementsAre("/nonexistent/heliostand/survey.csv: cannot read the survey: No such file or directory"));
}

TEST(ReadSurveyErrors, EmptyFileAndHeaderOnly) {
  EXPECT_THAT(problems_of(""), ElementsAre("s.csv: the survey is empty (expected a header row and one row per tree)"));
  EXPECT_THAT(problems_of("x,y,height\n\n"), ElementsAre("s.csv:1: no tree records after the header"));
}

TEST(ReadSurveyErrors, MissingRequiredColumns) {
  EXPECT_THAT(problems_of("id,x_m,dbh\n1,2,20\n"),
              ElementsAre("s.csv:1: column 'y': required column missing (accepted names: y, pos_y, position_y, y_coord, gy, each optionally with a unit: y_m)"));
  EXPECT_THAT(problems_of("x,y,crown_radius\n1,2,1.5\n"),
              ElementsAre("s.csv:1: column 'height': neither a height nor a dbh column; one of them is required "
                          "(accepted names: height, h, ht, tree_height, each optionally with a unit: height_m; dbh, d, d13, "
                          "diameter, diam, bhd, each optionally with a unit: dbh_cm)"));
}

TEST(ReadSurveyErrors, TwoHeadersForOneColumn) {
  EXPECT_THAT(problems_of("x,y,h,height\n1,1,15,15\n"),
              ElementsAre("s.csv:1: column 'height': names the same column as 'h' (column 3)"));
  EXPECT_THAT(problems_of("x,y,h,cr,cd\n1,1,15,1,2\n"),
              ElementsAre("s.csv:1: column 'cd': give either a crown radius ('cr') or a crown diameter column, not both"));
}

TEST(ReadSurveyErrors, NonNumericAndNonFiniteValues) {
  EXPECT_THAT(problems_of("x,y,height\n1,1,12abc\n2,1,1.5.2\n3,1,nan\n4,1,inf\n5,1,-inf\n"),
              ElementsAre("s.csv:2: column 'height': expected a number, got \"12abc\"",
                          "s.csv:3: column 'height': expected a number, got \"1.5.2\"",
                          "s.csv:4: column 'height': expected a finite number, got \"nan\"",
                          "s.csv:5: column 'height': expected a finite number, got \"inf\"",
                          "s.csv:6: column 'height': expected a finite number, got \"-inf\""));
}

TEST(ReadSurveyErrors, SizesMustBePositiveAndCrownBaseBelowHeight) {
  EXPECT_THAT(problems_of("x,y,h,dbh,crown_r,crown_base,age\n"
                          "1,1,-3,20,1.5,7,35\n"
                          "2,1,15,0,1.5,7,35\n"
                          "3,1,15,20,0,7,35\n"
                          "4,1,15,20,1.5,-1,35\n"
                          "5,1,15,20,1.5,15,35\n"
                          "6,1,15,20,1.5,0,0\n"),
              ElementsAre("s.csv:2: column 'h': expected a number > 0, got \"-3\"",
                          "s.csv:3: column 'dbh': expected a number > 0, got \"0\"",
                          "s.csv:4: column 'crown_r': expected a number > 0, got \"0\"",
                          "s.csv:5: column 'crown_base': expected a number >= 0, got \"-1\"",
                          "s.csv:6: column 'crown_base': crown base 15 m is not below the tree height 15 m",
                          "s.csv:7: column 'age': expected a number > 0, got \"0\""));
}

TEST(ReadSurveyErrors, RequiredCellsEmptyAndNothingToImputeFrom) {
  EXPECT_THAT(problems_of("x,y,height,dbh\n,1,15,20\n2,1,,\n3,1,1.2,\n"),
              ElementsAre("s.csv:2: column 'x': a value is required here (the cell is empty)",
                          "s.csv:3: column 'height': neither height nor dbh given for this tree (one of them is required)",
                          "s.csv:4: column 'dbh': no dbh given, and a tree 1.2 m tall is not above breast height (1.3 m) "
                          "to impute one"));
  SurveyReadOptions no_stand_age;
  EXPECT_THAT(problems_of("x,y,height,age\n1,1,15,\n", no_stand_age),
              ElementsAre("s.csv:2: column 'age': no age given, and no stand age to impute it from"));
}

TEST(ReadSurveyErrors, DuplicateIds) {
  EXPECT_THAT(problems_of("tree_id,x,y,h\n7,1,1,15\n8,2,1,15\n7,3,1,15\n"),
              ElementsAre("s.csv:4: column 'tree_id': duplicate id \"7\" (first used on line 2)"));
}

TEST(ReadSurveyErrors, TreesOutsideThePlot) {
  EXPECT_THAT(problems_of("x,y,h\n-0.5,1,15\n1,30.01,15\n31,-2,15\n"),
              ElementsAre("s.csv:2: column 'x': -0.5 is outside the plot (x from 0 to 30 m)",
                          "s.csv:3: column 'y': 30.01 is outside the plot (y from 0 to 30 m)",
                          "s.csv:4: column 'x': 31 is outside the plot (x from 0 to 30 m)",
                          "s.csv:4: column 'y': -2 is outside the plot (y from 0 to 30 m)"));
}

TEST(ReadSurveyErrors, TwoTreesAtOnePosition) {
  // 0.6 cm apart is one position; 2 cm apart are two trees.
  EXPECT_THAT(problems_of("x,y,h\n5,5,15\n8,8,15\n5.006,5,15\n8,8.02,15\n"),
              ElementsAre("s.csv:4: column 'x,y': stands within 1 cm of the tree on line 2 (two trees at one position; set "
                          "stand.multi_stem if these are the stems of one tree)"));
}

TEST(ReadSurveyErrors, WrongNumberOfFields) {
  EXPECT_THAT(problems_of("x,y,h\n1,1,15\n2,1\n3,1,15,4\n"),
              ElementsAre("s.csv:3: expected 3 fields (as in the header), got 2",
                          "s.csv:4: expected 3 fields (as in the header), got 4"));
}

TEST(ReadSurveyErrors, UnknownSpecies) {
  auto options = plot_30x30();
  options.species = {{"todomatsu", SpeciesParameters{}}};
  EXPECT_THAT(problems_of("x,y,h,species\n1,1,15,todomatsu\n2,1,15,ezomatsu\n", options),
              ElementsAre("s.csv:3: column 'species': unknown species \"ezomatsu\" (the scenario defines: todomatsu)"));
}

TEST(ReadSurveyErrors, ListsEveryProblemInLineOrder) {
  const auto lines = problems_of("id,x,y,h,dbh\n"
                                 "1,1,1,15,20\n"
                                 "2,40,1,abc,20\n"
                                 "1,3,1,15,-2\n"
                                 "4,1,1,15,20\n");
  EXPECT_THAT(lines, ElementsAre("s.csv:3: column 'h': expected a number, got \"abc\"",
                                 "s.csv:3: column 'x': 40 is outside the plot (x from 0 to 30 m)",
                                 "s.csv:4: column 'dbh': expected a number > 0, got \"-2\"",
                                 "s.csv:5: column 'x,y': stands within 1 cm of the tree on line 2 (two trees at one "
                                 "position; set stand.multi_stem if these are the stems of one tree)"));
}

}  // namespace
}  // namespace heliostand
