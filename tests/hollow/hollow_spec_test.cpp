// Invalid hollows are rejected before any geometry is built, each reason naming the HollowSpec field.
#include <gtest/gtest.h>

#include "hollow/hollow_spec.hpp"
#include "hollow/test_trunks.hpp"
#include "hollow/trunk_surface.hpp"

namespace heliostand::hollow {
namespace {

using testing::short_trunk;

// The single problem reported for a spec, as "field: reason".
std::vector<std::string> problems_of(const HollowSpec& spec) {
  std::vector<std::string> out;
  for (const auto& p : validate(spec, short_trunk())) out.push_back(p.field + ": " + p.reason);
  return out;
}

void expect_field(const HollowSpec& spec, const std::string& field, const std::string& words) {
  const auto problems = validate(spec, short_trunk());
  ASSERT_FALSE(problems.empty()) << "expected a problem with " << field;
  bool found = false;
  for (const auto& p : problems) {
    if (p.field != field) continue;
    found = true;
    EXPECT_NE(p.reason.find(words), std::string::npos) << p.reason;
  }
  EXPECT_TRUE(found) << "no problem names " << field << "; got " << problems[0].field << ": " << problems[0].reason;
}

TEST(HollowSpec, DefaultSpecIsValid) { EXPECT_TRUE(problems_of(HollowSpec{}).empty()); }

TEST(HollowSpec, SizesBelowFourSeedUnitsOrNegativeAreRejected) {
  HollowSpec s;
  s.width_m = 0.03;
  expect_field(s, "width_m", "≥ 0.04");
  s = {};
  s.wound_height_m = -0.2;
  expect_field(s, "wound_height_m", "≥ 0.04");
}

TEST(HollowSpec, CallusRadiusOutsideOneUnitToAQuarterOfTheWidthIsRejected) {
  HollowSpec s;
  s.callus_radius_m = 0.005;  // below 1 seed unit
  expect_field(s, "callus_radius_m", "[0.01, W/4");
  s.callus_radius_m = 0.031;  // W/4 = 0.03
  expect_field(s, "callus_radius_m", "W/4 = 0.03");
}

TEST(HollowSpec, BulgeOutsideZeroToQuarterWidthMinusRIsRejected) {
  HollowSpec s;  // W/4 − r = 0.03 − 0.015
  s.bulge_m = 0.016;
  expect_field(s, "bulge_m", "W/4 − r = 0.015");
  s.bulge_m = -0.001;
  expect_field(s, "bulge_m", "[0, W/4 − r");
  s.bulge_m = 0.015;
  EXPECT_TRUE(problems_of(s).empty());
}

TEST(HollowSpec, HollowAboveTheTreeTopOrBelowGroundIsRejected) {
  HollowSpec s;
  s.height_m = 19.9;
  expect_field(s, "height_m", "tree is 20.000 m tall");
  s.height_m = 0.05;
  expect_field(s, "height_m", "below ground");
  s.height_m = -1;
  expect_field(s, "height_m", "≥ 0");
}

TEST(HollowSpec, TangentPlaneWoundNoNarrowerThanTheStemIsRejected) {
  HollowSpec s;
  s.placement = Placement::tangent_plane;
  s.width_m = 0.34;  // the stem is 0.32 m across at 1.3 m
  s.callus_radius_m = 0.02;
  expect_field(s, "width_m", "tangent-plane placement");
  s.placement = Placement::cylindrical;
  EXPECT_TRUE(problems_of(s).empty());
}

TEST(HollowSpec, CylindricalWoundWrappingBeyondTheFlowsReachIsRejected) {
  HollowSpec s;
  s.width_m = 1.2;  // circumference ≈ 1.03 m
  s.callus_radius_m = 0.02;
  expect_field(s, "width_m", "80 % of half the circumference");
}

TEST(HollowSpec, MeshingParametersAreChecked) {
  HollowSpec s;
  s.polygon_corners = 3;
  expect_field(s, "polygon_corners", "[4, 36]");
  s = {};
  s.bark_line_spacing_m = 0;
  expect_field(s, "bark_line_spacing_m", "expected l");
  s = {};
  s.bark_segment_m = 1.0;
  expect_field(s, "bark_segment_m", "expected q");
  s = {};
  s.outline_step_m = 0.1;
  expect_field(s, "outline_step_m", "W/20");
}

TEST(HollowSpec, ProblemsFormatAsInputErrorLines) {
  HollowSpec s;
  s.bulge_m = 1.0;
  auto problems = validate(s, short_trunk());
  ASSERT_EQ(problems.size(), 1u);
  problems[0].file = "stands/trees.csv";
  problems[0].line = 4;
  EXPECT_EQ(problems[0].format("field").rfind("stands/trees.csv:4: field 'bulge_m': expected I in [0, W/4", 0), 0u);
}

}  // namespace
}  // namespace heliostand::hollow
