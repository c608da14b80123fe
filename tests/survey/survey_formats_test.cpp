// Tree lists as foresters have them: each separator, each unit suffix, each alias family, multi-stemmed trees
// both ways, and the plot taken from the data (docs/formats.md "Survey CSV").
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "survey/field_separator.hpp"
#include "survey/read_survey.hpp"
#include "survey/survey_test_files.hpp"

namespace heliostand {
namespace {

using testing::input_problems;
using testing::write_test_file;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

using testing::stand_of_age;

Survey read_text(const std::string& text, SurveyReadOptions options = stand_of_age()) {
  return read_survey(write_test_file("formats.csv", text), options);
}

std::vector<std::string> format_problems(const std::string& text, SurveyReadOptions options = stand_of_age()) {
  return testing::survey_problems("formats_bad.csv", text, options);
}

bool any_warning_contains(const Survey& survey, const std::string& text) {
  for (const auto& warning : survey.warnings)
    if (warning.find(text) != std::string::npos) return true;
  return false;
}

// --- separators ---

TEST(SurveySeparators, DetectedFromTheHeaderLine) {
  EXPECT_EQ(detect_field_separator("x,y,dbh\n1,2,3\n"), ',');
  EXPECT_EQ(detect_field_separator("x;y;dbh\n1,5;2;3\n"), ';');
  EXPECT_EQ(detect_field_separator("X\tY\tSpecies\n"), '\t');
  EXPECT_EQ(detect_field_separator("\n\n\"a;b\",c,d\n"), ',');  // quoted semicolons and leading blank lines
  EXPECT_EQ(detect_field_separator("height\n12\n"), ',');       // one column
}

TEST(SurveySeparators, CommaSemicolonAndTabFilesReadTheSame) {
  for (const std::string text : {"id,x,y,height,dbh\nA,1.5,2,15,20\n", "id;x;y;height;dbh\nA;1,5;2;15;20\n",
                                 "id\tx\ty\theight\tdbh\nA\t1.5\t2\t15\t20\n"}) {
    const Survey survey = read_text(text);
    ASSERT_EQ(survey.trees.size(), 1u) << text;
    EXPECT_DOUBLE_EQ(survey.trees[0].x_m, 1.5) << text;
    EXPECT_DOUBLE_EQ(survey.trees[0].dbh_cm, 20.0) << text;
  }
}

TEST(SurveySeparators, DecimalCommaOnlyWhereTheCommaCannotSeparate) {
  // In a comma file "1,5" is two fields; in a semicolon file it is 1.5, but "1,234.5" stays an error.
  EXPECT_THAT(format_problems("x;y;height\n1,234.5;2;15\n"),
              ElementsAre("s.csv:2: column 'x': expected a number, got \"1,234.5\""));
}

TEST(SurveySeparators, TheScenarioMayNameTheSeparator) {
  // A comma-separated file whose header holds a semicolon inside a name: detection would pick ';'.
  SurveyReadOptions options = stand_of_age();
  options.format.separator = FieldSeparator::comma;
  const Survey survey = read_text("x,y,height,\"note;remark\"\n1,2,15,a\n", options);
  ASSERT_EQ(survey.trees.size(), 1u);
  EXPECT_DOUBLE_EQ(survey.trees[0].height_m, 15.0);
  EXPECT_THAT(format_problems("x,y,height\n1,2,15\n", [] {
                SurveyReadOptions o = stand_of_age();
                o.format.separator = FieldSeparator::tab;
                return o;
              }()),
              ElementsAre(HasSubstr("column 'x': required column missing"), HasSubstr("column 'y': required column missing"),
                          HasSubstr("column 'height': neither a height nor a dbh column")));
}

// --- units ---

TEST(SurveyUnits, HeaderSuffixesConvertToCanonicalUnits) {
  struct Case {
    std::string header;
    double value;
    double SurveyRecord::*field;
    double expected;
  };
  const std::vector<Case> cases{
      {"dbh_m", 0.211, &SurveyRecord::dbh_cm, 21.1},       {"dbh_mm", 211, &SurveyRecord::dbh_cm, 21.1},
      {"dbh_cm", 21.1, &SurveyRecord::dbh_cm, 21.1},       {"dbh_in", 10, &SurveyRecord::dbh_cm, 25.4},
      {"DBH (cm)", 21.1, &SurveyRecord::dbh_cm, 21.1},     {"d [mm]", 211, &SurveyRecord::dbh_cm, 21.1},
      {"height_ft", 50, &SurveyRecord::height_m, 15.24},   {"crown_radius_ft", 10, &SurveyRecord::crown_radius_m, 3.048},
      {"crown_base_dm", 71, &SurveyRecord::crown_base_m, 7.1}, {"age_years", 40, &SurveyRecord::age_years, 40},
  };
  for (const Case& c : cases) {
    const std::string other = c.header.rfind("height", 0) == 0 ? "dbh" : "height";
    const double other_value = other == "dbh" ? 20 : 15.8;
    const Survey survey = read_text(fmt::format("x,y,{},\"{}\"\n1,2,{},{}\n", other, c.header, other_value, c.value));
    ASSERT_EQ(survey.trees.size(), 1u) << c.header;
    EXPECT_NEAR(survey.trees[0].*c.field, c.expected, 1e-9) << c.header;
  }
}

TEST(SurveyUnits, PositionsInFeetAndTheScenariosPerColumnUnit) {
  SurveyReadOptions options = stand_of_age();
  options.format.units = {{SurveyColumn::dbh, "mm"}, {SurveyColumn::x, "ft"}};
  const Survey survey = read_text("x,y,height,dbh\n10,2,15,205\n", options);
  EXPECT_NEAR(survey.trees[0].x_m, 3.048, 1e-12);
  EXPECT_NEAR(survey.trees[0].dbh_cm, 20.5, 1e-12);
}

TEST(SurveyUnits, UnitsThatDoNotFitOrDisagreeAreErrors) {
  EXPECT_THAT(format_problems("x,y,height_pct\n1,2,15\n"),
              ElementsAre("s.csv:1: column 'height_pct': 'pct' is not a unit of height (accepted: m, cm, mm, dm, ft, "
                          "in)"));
  SurveyReadOptions options = stand_of_age();
  options.format.units = {{SurveyColumn::dbh, "mm"}};
  EXPECT_THAT(format_problems("x,y,dbh_cm\n1,2,20\n", options),
              ElementsAre("s.csv:1: column 'dbh_cm': the header says the unit is 'cm' but the scenario's survey_units "
                          "says 'mm'"));
}

TEST(SurveyUnits, ANameThatEndsLikeAUnitIsStillMatchedWholeFirst) {
  // "tree_id" is an alias of id, not "tree" in units "id"; "crown_base_height_m" is crown base in m.
  const Survey survey = read_text("tree_id,x,y,h,crown_base_height_m\nT1,1,2,15,7\n");
  EXPECT_EQ(survey.trees[0].id, "T1");
  EXPECT_DOUBLE_EQ(survey.trees[0].crown_base_m, 7.0);
}

// --- alias families ---

TEST(SurveyAliases, ILandTreeList) {
  const Survey trees = read_text("id;x;y;species;bhd;height;age\n7;10,5;3;piab;32,1;27,4;80\n");
  ASSERT_EQ(trees.trees.size(), 1u);
  EXPECT_EQ(trees.trees[0].species, "piab");
  EXPECT_DOUBLE_EQ(trees.trees[0].dbh_cm, 32.1);
  EXPECT_DOUBLE_EQ(trees.trees[0].height_m, 27.4);
  EXPECT_DOUBLE_EQ(trees.trees[0].age_years, 80);
}

TEST(SurveyAliases, SortieTabTreeMapSkipsSeedlingsAndSnags) {
  const Survey survey = read_text("X\tY\tSpecies\tType\tDiam\tHeight\n"
                                  "10.34\t62.1\tMaple\tSeedling\t0.2\t0.4\n"
                                  "9.33\t88.97\tBeech\tSapling\t4.567\t5.2\n"
                                  "5.73\t65.16\tHemlock\tAdult\t15.887\t15.3\n"
                                  "127.03\t146.6\tBeech\tSnag\t35.41\t28.7\n");
  ASSERT_EQ(survey.trees.size(), 2u);
  EXPECT_EQ(survey.trees[0].species, "Beech");
  EXPECT_DOUBLE_EQ(survey.trees[1].dbh_cm, 15.887);
  EXPECT_TRUE(any_warning_contains(survey, "1 seedlings and 1 snags or other dead stems skipped"));
  EXPECT_THAT(format_problems("X\tY\tType\tDiam\n1\t2\tTeenager\t10\n"),
              ElementsAre(HasSubstr("s.csv:2: column 'Type': unknown life stage \"teenager\"")));
}

TEST(SurveyAliases, FvsTreeRecordsInImperialUnitsWithCrownRatioInPercent) {
  SurveyReadOptions options = stand_of_age();
  options.format.units = {{SurveyColumn::dbh, "in"}, {SurveyColumn::height, "ft"}, {SurveyColumn::crown_ratio, "pct"},
                          {SurveyColumn::x, "ft"}, {SurveyColumn::y, "ft"}};
  const Survey survey = read_text("Tree_ID,X,Y,Species,DBH,Ht,CrRatio\n12,30,40,DF,10,100,40\n", options);
  ASSERT_EQ(survey.trees.size(), 1u);
  const SurveyRecord& t = survey.trees[0];
  EXPECT_EQ(t.id, "12");
  EXPECT_NEAR(t.dbh_cm, 25.4, 1e-12);
  EXPECT_NEAR(t.height_m, 30.48, 1e-12);
  EXPECT_NEAR(t.crown_base_m, 30.48 * 0.6, 1e-12);  // a 40 % live crown
  EXPECT_NEAR(t.y_m, 12.192, 1e-12);
}

TEST(SurveyAliases, ForestGeoCensus) {
  const Survey survey = read_text("tag,gx,gy,sp,dbh_mm\n100023,412.3,87.1,pinupo,231\n");
  EXPECT_EQ(survey.trees[0].id, "100023");
  EXPECT_DOUBLE_EQ(survey.trees[0].x_m, 412.3);
  EXPECT_NEAR(survey.trees[0].dbh_cm, 23.1, 1e-12);
}

TEST(SurveyAliases, CrownBaseAndCrownRatioTogetherAreAnError) {
  EXPECT_THAT(format_problems("x,y,h,crown_base,crown_ratio\n1,2,15,7,0.5\n"),
              ElementsAre("s.csv:1: column 'crown_ratio': give either a crown base ('crown_base') or a crown ratio "
                          "column, not both"));
}

// --- multi-stemmed trees ---

const std::string two_double_stems = "id,x,y,height,dbh,crown_radius,species\n"
                                     "A,1,1,15,20,2,ta\n"
                                     "B,1.004,1,12,15,1.5,ta\n"
                                     "C,5,5,15,20,2,ta\n"
                                     "D,5,5.008,16,10,1,ta\n"
                                     "E,9,9,14,18,2,ta\n";

TEST(MultiStemmedTrees, RefusedByDefault) {
  EXPECT_EQ(format_problems(two_double_stems).size(), 2u);
}

TEST(MultiStemmedTrees, KeptAsSeparateTrees) {
  SurveyReadOptions options = stand_of_age();
  options.format.multi_stem = MultiStemPolicy::separate;
  const Survey survey = read_text(two_double_stems, options);
  EXPECT_EQ(survey.trees.size(), 5u);
  EXPECT_TRUE(any_warning_contains(survey, "4 stems stand at 2 shared positions; kept as separate trees"));
}

TEST(MultiStemmedTrees, MergedByBasalArea) {
  SurveyReadOptions options = stand_of_age();
  options.format.multi_stem = MultiStemPolicy::merge;
  const Survey survey = read_text(two_double_stems, options);
  ASSERT_EQ(survey.trees.size(), 3u);
  const SurveyRecord& a = survey.trees[0];
  EXPECT_EQ(a.id, "A");
  EXPECT_NEAR(a.dbh_cm, 25.0, 1e-12);              // sqrt(20² + 15²)
  EXPECT_NEAR(a.crown_radius_m, 2.5, 1e-12);       // sqrt(2² + 1.5²)
  EXPECT_DOUBLE_EQ(a.height_m, 15.0);
  EXPECT_EQ(survey.trees[1].id, "C");
  EXPECT_DOUBLE_EQ(survey.trees[1].height_m, 16.0);
  EXPECT_EQ(survey.trees[2].id, "E");
  EXPECT_TRUE(any_warning_contains(survey, "4 stems at 2 shared positions merged into 2 trees"));
}

TEST(MultiStemmedTrees, StemsOfTwoSpeciesCannotBeMerged) {
  SurveyReadOptions options = stand_of_age();
  options.format.multi_stem = MultiStemPolicy::merge;
  EXPECT_THAT(format_problems("x,y,h,species\n1,1,15,ta\n1,1,12,bi\n", options),
              ElementsAre("s.csv:2: column 'x,y': stems of one tree must be of one species: line 2 is \"ta\", line 3 "
                          "\"bi\""));
}

// --- plot from the data ---

TEST(SurveyExtent, SpansTheStemPositionsInTheFilesUnits) {
  SurveyFormat format;
  format.units = {{SurveyColumn::x, "cm"}};
  const auto extent = survey_extent(write_test_file("extent.csv", "x;y;h\n100;2;15\n350;-4;12\nbad;1;3\n"), format);
  ASSERT_TRUE(extent);
  EXPECT_DOUBLE_EQ(extent->x_min, 1.0);
  EXPECT_DOUBLE_EQ(extent->x_max, 3.5);
  EXPECT_DOUBLE_EQ(extent->y_min, -4.0);
  EXPECT_DOUBLE_EQ(extent->y_max, 2.0);
  EXPECT_FALSE(survey_extent(write_test_file("extent_empty.csv", "x,y,h\n")));
  EXPECT_FALSE(survey_extent("/nonexistent/heliostand/extent.csv"));
}

}  // namespace
}  // namespace heliostand
