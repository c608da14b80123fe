#include "roots/soil_file.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "core/input_error.hpp"

namespace heliostand::roots {
namespace {

SoilGrid one_cell_grid() { return SoilGrid({{0.0, 0.0, -1.0}, 1.0, {1, 1, 1}}, 1.0, 0.5); }  // 2 × 2 × 2 vertices

std::vector<InputProblem> problems_of(const std::string& text, SoilGrid& soil) {
  std::istringstream in(text);
  try {
    read_soil_csv(in, "soil.csv", soil);
  } catch (const InputError& error) {
    return error.problems();
  }
  return {};
}

TEST(SoilFile, SetsListedVerticesAndTheirCapacity) {
  SoilGrid soil = one_cell_grid();
  std::istringstream in("# wet corner\n\ni,j,k,moisture,nutrient\n0,0,0,0.25,0.75\n1, 1, 1, 0.5 ,1.0\n");
  read_soil_csv(in, "soil.csv", soil);
  EXPECT_DOUBLE_EQ(soil.at(SoilField::moisture, 0, 0, 0), 0.25);
  EXPECT_DOUBLE_EQ(soil.at(SoilField::nutrient, 0, 0, 0), 0.75);
  EXPECT_DOUBLE_EQ(soil.at(SoilField::moisture, 1, 1, 1), 0.5);
  EXPECT_DOUBLE_EQ(soil.at(SoilField::moisture, 1, 0, 0), 1.0);  // not listed: kept
  EXPECT_DOUBLE_EQ(soil.capacity(SoilField::moisture)[soil.vertex_index(0, 0, 0)], 0.25);
}

TEST(SoilFile, ColumnsInAnyOrderAndOnlyOneField) {
  SoilGrid soil = one_cell_grid();
  std::istringstream in("nutrient,k,j,i\n0.1,1,0,1\n");
  read_soil_csv(in, "soil.csv", soil);
  EXPECT_DOUBLE_EQ(soil.at(SoilField::nutrient, 1, 0, 1), 0.1);
  EXPECT_DOUBLE_EQ(soil.at(SoilField::moisture, 1, 0, 1), 1.0);
}

TEST(SoilFile, EveryBadValueIsReportedWithLineAndColumn) {
  SoilGrid soil = one_cell_grid();
  const auto problems = problems_of(
      "i,j,k,moisture\n"
      "0,0,0,wet\n"   // line 2
      "0,0,2,0.5\n"   // line 3: k out of range
      "0,1,0,-0.1\n"  // line 4: negative
      "1,0,0,0.2\n"   // line 5: fine
      "1,0,0,0.3\n"   // line 6: duplicate of line 5
      "1,1\n",        // line 7: too few fields
      soil);
  ASSERT_EQ(problems.size(), 5u);
  EXPECT_EQ(problems[0].format(), "soil.csv:2: column 'moisture': expected a number >= 0, got \"wet\"");
  EXPECT_EQ(problems[1].format(), "soil.csv:3: column 'k': expected a vertex index 0..1, got \"2\"");
  EXPECT_EQ(problems[2].line, 4);
  EXPECT_EQ(problems[2].field, "moisture");
  EXPECT_EQ(problems[3].line, 6);
  EXPECT_NE(problems[3].reason.find("listed twice"), std::string::npos);
  EXPECT_EQ(problems[4].format(), "soil.csv:7: expected 4 fields, got 2");
  // A bad file leaves the grid as it was (line 5 was good but is not applied).
  EXPECT_DOUBLE_EQ(soil.at(SoilField::moisture, 1, 0, 0), 1.0);
}

TEST(SoilFile, BadHeaderAndMissingFile) {
  SoilGrid soil = one_cell_grid();
  auto header_problems = problems_of("i,j,depth,moisture\n", soil);
  ASSERT_EQ(header_problems.size(), 2u);
  EXPECT_EQ(header_problems[0].field, "depth");
  EXPECT_EQ(header_problems[1].format(), "soil.csv:1: column 'k': missing column");
  EXPECT_EQ(problems_of("i,j,k\n", soil).at(0).reason, "need a moisture or a nutrient column");
  EXPECT_EQ(problems_of("# only a comment\n", soil).at(0).line, 0);
  try {
    read_soil_csv("/nonexistent/soil.csv", soil);
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.problems().at(0).format(), "/nonexistent/soil.csv: cannot open the soil file");
  }
}

}  // namespace
}  // namespace heliostand::roots
