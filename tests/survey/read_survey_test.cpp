#include "survey/read_survey.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "survey/survey_allometry.hpp"
#include "survey/survey_test_files.hpp"

namespace heliostand {
namespace {

using testing::input_problems;
using testing::write_test_file;
using ::testing::ElementsAre;

using testing::plot_30x30;

// ---------------------------------------------------------------------------------------------- good files

TEST(ReadSurvey, ReadsACompleteFileWithoutWarnings) {
  const auto file = write_test_file("complete.csv",
                                    "id,x,y,height,dbh,crown_radius,crown_base,age,species\n"
                                    "T1,1.5,2.0,16.2,21.4,1.8,7.5,35,todomatsu\n"
                                    "T2,3.5,2.1,14.8,18.0,1.4,6.9,34,todomatsu\n");
  const Survey survey = read_survey(file, plot_30x30());
  ASSERT_EQ(survey.trees.size(), 2u);
  EXPECT_TRUE(survey.warnings.empty());
  const SurveyRecord& t = survey.trees[1];
  EXPECT_EQ(t.id, "T2");
  EXPECT_EQ(t.line, 3);
  EXPECT_DOUBLE_EQ(t.x_m, 3.5);
  EXPECT_DOUBLE_EQ(t.y_m, 2.1);
  EXPECT_DOUBLE_EQ(t.height_m, 14.8);
  EXPECT_DOUBLE_EQ(t.dbh_cm, 18.0);
  EXPECT_DOUBLE_EQ(t.crown_radius_m, 1.4);
  EXPECT_DOUBLE_EQ(t.crown_base_m, 6.9);
  EXPECT_DOUBLE_EQ(t.age_years, 34);
  EXPECT_EQ(t.species, "todomatsu");
  EXPECT_FALSE(t.imputed.height || t.imputed.dbh || t.imputed.crown_radius || t.imputed.crown_base ||
               t.imputed.age || t.imputed.id || t.imputed.species);
}

TEST(ReadSurvey, AcceptsAliasesInAnyCaseAndOrder) {
  const auto file = write_test_file("aliases.csv",
                                    "Tree_ID, X_m ,Y-M,H,DBH_cm,Crown R,HCB,Age_Years,SP\n"
                                    "a,1,1,15,20,1.5,7,35,todomatsu\n");
  const Survey survey = read_survey(file, plot_30x30());
  ASSERT_EQ(survey.trees.size(), 1u);
  const SurveyRecord& t = survey.trees[0];
  EXPECT_EQ(t.id, "a");
  EXPECT_DOUBLE_EQ(t.height_m, 15);
  EXPECT_DOUBLE_EQ(t.dbh_cm, 20);
  EXPECT_DOUBLE_EQ(t.crown_radius_m, 1.5);
  EXPECT_DOUBLE_EQ(t.crown_base_m, 7);
  EXPECT_TRUE(survey.warnings.empty());
}

TEST(ReadSurvey, CrownDiameterGivesHalfAsRadius) {
  const auto file = write_test_file("diameter.csv", "x,y,h,d,crown_diameter,hcb\n1,1,15,20,3.2,7\n");
  const Survey survey = read_survey(file, plot_30x30());
  EXPECT_DOUBLE_EQ(survey.trees[0].crown_radius_m, 1.6);
}

TEST(ReadSurvey, MissingCrownDiameterIsImputedAsARadiusWithAWarning) {
  const auto file = write_test_file("diameter_gap.csv", "x,y,h,d,crown_diameter,hcb\n1,1,15,20,3.2,7\n2,1,15,20,,7\n");
  const Survey survey = read_survey(file, plot_30x30());
  EXPECT_DOUBLE_EQ(survey.trees[1].crown_radius_m, 1.65);  // 0.25 + 0.07 x 20
  EXPECT_TRUE(survey.trees[1].imputed.crown_radius);
  EXPECT_THAT(survey.warnings, ElementsAre(file.string() + ": column 'crown_diameter': 1 of 2 values missing; crown "
                                                           "radius imputed as 0.25 m + 0.07 m/cm x DBH"));
}

TEST(ReadSurvey, QuotedFieldsAndSpacesAroundNumbers) {
  const auto file = write_test_file("quoted.csv",
                                    "id,x,y,height,dbh,species\n"
                                    "\"T, 1\",\" 1.25 \",+2,16,\"21.5\",todomatsu\n");
  const Survey survey = read_survey(file, plot_30x30());
  ASSERT_EQ(survey.trees.size(), 1u);
  EXPECT_EQ(survey.trees[0].id, "T, 1");
  EXPECT_DOUBLE_EQ(survey.trees[0].x_m, 1.25);
  EXPECT_DOUBLE_EQ(survey.trees[0].y_m, 2);
}

TEST(ReadSurvey, ImputesMissingValuesWithOneWarningPerColumn) {
  // Tree on line 2 lacks DBH, line 3 lacks height, line 4 lacks crown values and age; id only on line 4.
  const auto file = write_test_file("gaps.csv",
                                    "id,x,y,height,dbh,crown_radius,crown_base,age\n"
                                    ",1,1,16,,1.5,7,30\n"
                                    ",3,1,,20,1.5,7,30\n"
                                    "X,5,1,12,20,,,\n");
  const Survey survey = read_survey(file, plot_30x30(35));
  ASSERT_EQ(survey.trees.size(), 3u);
  const auto& a = survey.trees[0];
  const auto& b = survey.trees[1];
  const auto& c = survey.trees[2];
  // id = line number
  EXPECT_EQ(a.id, "2");
  EXPECT_TRUE(a.imputed.id);
  EXPECT_EQ(c.id, "X");
  // DBH from height by seed 001 eq. 2 below the crown: 3.336 (16 - 1.3)^0.771 = 26.499 cm.
  EXPECT_NEAR(a.dbh_cm, 26.499, 1e-3);
  EXPECT_TRUE(a.imputed.dbh);
  // Height from DBH by the inverse: 1.3 + (20 / 3.336)^(1 / 0.771) = 11.505 m.
  EXPECT_NEAR(b.height_m, 11.505, 1e-3);
  EXPECT_TRUE(b.imputed.height);
  // Crown radius 0.25 + 0.07 x 20 = 1.65 m, crown base 0.45 x 12 = 5.4 m, age = stand age 35.
  EXPECT_DOUBLE_EQ(c.crown_radius_m, 1.65);
  EXPECT_DOUBLE_EQ(c.crown_base_m, 5.4);
  EXPECT_DOUBLE_EQ(c.age_years, 35);
  EXPECT_TRUE(c.imputed.crown_radius && c.imputed.crown_base && c.imputed.age);
  EXPECT_FALSE(c.imputed.height || c.imputed.dbh);
  // Species column absent: every tree gets the default species.
  EXPECT_EQ(c.species, "todomatsu");

  const std::string f = file.string();
  EXPECT_THAT(survey.warnings,
              ElementsAre(f + ": column 'id': 2 of 3 values missing; using the line number as id",
                          f + ": column 'height': 1 of 3 values missing; imputed from DBH by seed 001 eq. 2 "
                              "(below-crown coefficients), inverted",
                          f + ": column 'dbh': 1 of 3 values missing; imputed from height by seed 001 eq. 2 "
                              "(below-crown coefficients)",
                          f + ": column 'crown_radius': 1 of 3 values missing; crown radius imputed as 0.25 m + 0.07 m/cm x "
                              "DBH",
                          f + ": column 'crown_base': 1 of 3 values missing; imputed as 0.45 x height",
                          f + ": column 'age': 1 of 3 values missing; using the stand age at the survey, 35 years"));
  // No warning about species: without a species column every tree is of the scenario's default species.
}

TEST(ReadSurvey, ImputationUsesTheRecordsSpeciesStemCurve) {
  SpeciesParameters stout;
  stout.name = "stout";
  stout.stem_a_below_crown = 4.0;
  stout.stem_b_below_crown = 1.0;
  auto options = plot_30x30();
  options.species = {{"todomatsu", SpeciesParameters{}}, {"stout", stout}};
  const auto file = write_test_file("species.csv", "x,y,height,species\n1,1,11.3,stout\n");
  const Survey survey = read_survey(file, options);
  EXPECT_DOUBLE_EQ(survey.trees[0].dbh_cm, 40.0);  // 4.0 x (11.3 - 1.3)^1
}

TEST(ReadSurvey, IgnoresUnknownColumnsWithAWarning) {
  const auto file = write_test_file("extra.csv", "x,y,h,d,hcb,cr,notes\n1,1,15,20,7,1.5,leaning\n");
  const Survey survey = read_survey(file, plot_30x30());
  ASSERT_EQ(survey.trees.size(), 1u);
  EXPECT_THAT(survey.warnings,
              ElementsAre(file.string() + ": column 'notes' is not a survey column; ignored"));
}

TEST(ReadSurvey, EmptySpeciesCellsGetTheDefaultSpeciesWithAWarning) {
  auto options = plot_30x30();
  options.default_species = "ezomatsu";
  const auto file = write_test_file("species_gap.csv", "x,y,h,d,hcb,cr,species\n1,1,15,20,7,1.5,todomatsu\n2,1,15,20,7,1.5,\n");
  const Survey survey = read_survey(file, options);
  EXPECT_EQ(survey.trees[0].species, "todomatsu");
  EXPECT_EQ(survey.trees[1].species, "ezomatsu");
  EXPECT_TRUE(survey.trees[1].imputed.species);
  EXPECT_THAT(survey.warnings, ElementsAre(file.string() + ": column 'species': 1 of 2 values missing; using the "
                                                           "default species 'ezomatsu'"));
}

TEST(ReadSurvey, TreesOnThePlotEdgeAreInside) {
  const auto file = write_test_file("edge.csv", "x,y,h\n0,0,15\n30,30,15\n");
  EXPECT_EQ(read_survey(file, plot_30x30()).trees.size(), 2u);
}

}  // namespace
}  // namespace heliostand
