// The survey's `hollow` column: cells read into hollows, and every bad cell reported at its line with the
// tree and the hollow field (docs/formats.md, "Survey CSV").
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "survey/hollow_cell.hpp"
#include "survey/read_survey.hpp"
#include "survey/survey_test_files.hpp"

namespace heliostand {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using testing::input_problems;
using testing::write_test_file;

const std::string header = "id,x,y,height,dbh,crown_base,age,Cavity\n";

TEST(HollowCell, EmptyCellIsNoHollow) {
  auto parsed = parse_hollow_cell("  ");
  ASSERT_TRUE(std::holds_alternative<std::vector<hollow::HollowSpec>>(parsed));
  EXPECT_TRUE(std::get<std::vector<hollow::HollowSpec>>(parsed).empty());
}

TEST(HollowCell, HeightAndAzimuthOrTheFullEntranceSeveralPerCell) {
  auto parsed = parse_hollow_cell("1.4/135; 3.2/300/0.08/0.15");
  ASSERT_TRUE(std::holds_alternative<std::vector<hollow::HollowSpec>>(parsed)) << std::get<std::string>(parsed);
  const auto& hollows = std::get<std::vector<hollow::HollowSpec>>(parsed);
  ASSERT_EQ(hollows.size(), 2u);
  EXPECT_DOUBLE_EQ(hollows[0].height_m, 1.4);
  EXPECT_DOUBLE_EQ(hollows[0].azimuth_deg, 135);
  EXPECT_DOUBLE_EQ(hollows[0].width_m, hollow::HollowSpec{}.width_m);  // not given: the default entrance
  EXPECT_DOUBLE_EQ(hollows[1].height_m, 3.2);
  EXPECT_DOUBLE_EQ(hollows[1].azimuth_deg, 300);
  EXPECT_DOUBLE_EQ(hollows[1].width_m, 0.08);
  EXPECT_DOUBLE_EQ(hollows[1].wound_height_m, 0.15);
  // The callus roll follows the entrance: r = W/8 = 0.01 m, I = W/4 − r = 0.01 m.
  EXPECT_DOUBLE_EQ(hollows[1].callus_radius_m, 0.01);
  EXPECT_DOUBLE_EQ(hollows[1].bulge_m, 0.01);
  // A 5 cm hole: r at its 1 cm minimum, I = 0.0125 − 0.01.
  const auto small = std::get<std::vector<hollow::HollowSpec>>(parse_hollow_cell("2/0/0.05/0.08"));
  EXPECT_DOUBLE_EQ(small[0].callus_radius_m, 0.01);
  EXPECT_NEAR(small[0].bulge_m, 0.0025, 1e-12);
}

TEST(HollowCell, BadCellsSayWhichHollowAndField) {
  EXPECT_EQ(std::get<std::string>(parse_hollow_cell("1.3")),
            "hollow 1: expected HEIGHT_M/AZIMUTH_DEG or HEIGHT_M/AZIMUTH_DEG/WIDTH_M/WOUND_HEIGHT_M, got \"1.3\"");
  EXPECT_EQ(std::get<std::string>(parse_hollow_cell("1.3/90;2/east")),
            "hollow 2: azimuth_deg: expected a number, got \"east\"");
  EXPECT_EQ(std::get<std::string>(parse_hollow_cell("1.3/90/0.1")),
            "hollow 1: expected HEIGHT_M/AZIMUTH_DEG or HEIGHT_M/AZIMUTH_DEG/WIDTH_M/WOUND_HEIGHT_M, got \"1.3/90/0.1\"");
}

TEST(SurveyHollows, RecordsCarryTheirHollowsWithWhereTheyWereWritten) {
  const auto file = write_test_file("hollows/good.csv", header +
                                                            "1,2,2,9,12,4,30,1.3/90\n"
                                                            "2,7,2,10,13,4.2,30,\n");
  const Survey survey = read_survey(file);
  ASSERT_EQ(survey.trees.size(), 2u);
  ASSERT_EQ(survey.trees[0].hollows.size(), 1u);
  const TreeHollow& hollow = survey.trees[0].hollows[0];
  EXPECT_DOUBLE_EQ(hollow.spec.height_m, 1.3);
  EXPECT_DOUBLE_EQ(hollow.spec.azimuth_deg, 90);
  EXPECT_FALSE(hollow.seed_given);
  EXPECT_EQ(hollow.line, 2);
  EXPECT_EQ(hollow.field, "Cavity");  // the header as written
  EXPECT_EQ(hollow.field_kind, "column");
  EXPECT_TRUE(survey.trees[1].hollows.empty());
}

TEST(SurveyHollows, HollowsTheTrunkCannotCarryAreErrorsNamingTreeAndField) {
  // Tree "1" is 9 m tall (hollows must stay below 95 %, 8.55 m); its stem radius at 1.3 m is about 8 cm, so
  // half its circumference is about 25 cm: a 0.6 m wide wound cannot wrap it.
  const auto file = write_test_file("hollows/bad.csv", header +
                                                           "1,2,2,9,12,4,30,8.8/0\n"
                                                           "2,7,2,9,12,4,30,1.3/0/0.6/0.2\n"
                                                           "3,2,7,9,12,4,30,1.3/0/-0.1/0.2\n"
                                                           "4,7,7,9,12,4,30,1.3/north\n");
  const auto problems = input_problems([&] { read_survey(file); });
  const std::string at = file.string() + ":";
  ASSERT_EQ(problems.size(), 4u) << ::testing::PrintToString(problems);
  EXPECT_THAT(problems[0], HasSubstr(at + "2: column 'Cavity': tree \"1\", hollow 1: height_m: the hollow reaches"));
  EXPECT_THAT(problems[0], HasSubstr("must stay below 8.550 m"));
  EXPECT_THAT(problems[1], HasSubstr(at + "3: column 'Cavity': tree \"2\", hollow 1: width_m: 0.6 m is too wide"));
  EXPECT_EQ(problems[2], at + "4: column 'Cavity': hollow 1: width_m: expected a number > 0, got \"-0.1\"");
  EXPECT_EQ(problems[3], at + "5: column 'Cavity': hollow 1: azimuth_deg: expected a number, got \"north\"");
}

TEST(SurveyHollows, SeveralHollowsOnOneTreeMustBeStackedApart) {
  const auto good = write_test_file("hollows/two.csv", header + "1,2,2,9,12,4,30,1.3/90;4.0/270/0.06/0.1\n");
  ASSERT_EQ(read_survey(good).trees[0].hollows.size(), 2u);

  // 20 cm apart: the two bark patches overlap (each reaches about twice the wound height around it).
  const auto clash = write_test_file("hollows/clash.csv", header + "1,2,2,9,12,4,30,1.3/90;1.5/270\n");
  const auto problems = input_problems([&] { read_survey(clash); });
  ASSERT_EQ(problems.size(), 1u) << ::testing::PrintToString(problems);
  EXPECT_THAT(problems[0], HasSubstr(clash.string() + ":2: column 'Cavity': tree \"1\", hollow 2: height_m: its bark "
                                                      "patch"));
  EXPECT_THAT(problems[0], HasSubstr("of hollow 1 of column 'Cavity' at 1.3 m"));
}

}  // namespace
}  // namespace heliostand
