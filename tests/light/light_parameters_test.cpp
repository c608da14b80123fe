// The light's distances (the near field's cut-off and the far field's cell) are bounded by validate(), and the
// solvers are right up to the bound: far beyond it they failed without a word (a cut-off of 1e160 m made the light
// 0.61 too bright on average, a 1e100 m cell gave the OpenCL far field NaN light; light/light_parameters.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "compute/opencl_test_backend.hpp"
#include "light/celestial_sphere.hpp"
#include "light/light_parameters.hpp"
#include "light/make_light_solver.hpp"
#include "light/reference_light_solver.hpp"
#include "light_test_stands.hpp"

namespace heliostand {
namespace {

// The message validate() gives `p`, or "" where it accepts it.
std::string refusal(const LightParameters& p) {
  try {
    validate(p);
    return "";
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
}

TEST(LightParameters, DistancesBeyondOneKilometreAreRefusedByName) {
  EXPECT_EQ(max_light_distance_m, 1000.0);
  for (const double metres : {0.0, -1.0, 1000.001, 1e100, 1e160}) {
    LightParameters cutoff;
    cutoff.cutoff_m = metres;
    EXPECT_NE(refusal(cutoff).find("light.cutoff_m: expected a distance in (0, 1000] m"), std::string::npos)
        << metres << ": " << refusal(cutoff);
    LightParameters cell;
    cell.far_field_cell_m = metres;
    EXPECT_NE(refusal(cell).find("light.far_field_cell_m: expected a distance in (0, 1000] m"), std::string::npos)
        << metres << ": " << refusal(cell);
  }
  LightParameters longest;
  longest.cutoff_m = longest.far_field_cell_m = max_light_distance_m;
  EXPECT_EQ(refusal(longest), "");
}

// 100 random balls in a 6 m cube (seed 3), shaded somewhere below 0.8.
std::vector<LeafBall> shaded_stand(const LightParameters& p) {
  return testing::random_stand(100, 6.0, 0.2, 0.7, 3, CelestialSphere(p), false);
}

// `actual` light against `expected`, ball by ball, within `tolerance`; every value finite.
void expect_light(const std::vector<LightSample>& actual, const std::vector<LightSample>& expected, double tolerance,
                  const std::string& label) {
  ASSERT_EQ(actual.size(), expected.size()) << label;
  double lowest = 1;
  for (std::size_t k = 0; k < expected.size(); ++k) {
    lowest = std::min(lowest, expected[k].light);
    ASSERT_TRUE(std::isfinite(actual[k].light)) << label << ", ball " << k;
    EXPECT_NEAR(actual[k].light, expected[k].light, tolerance) << label << ", ball " << k;
  }
  EXPECT_LT(lowest, 0.8) << label;  // there is shade to get right
}

// At the longest cut-off every occluder is near field, so the culled solvers give the exact light (the reference's
// to round-off, the device's to float). At the longest cell the far field is one voxel a thousand times wider than
// the stand, whose shade it spreads to nothing: the culled light is the near field's alone (the far field off), and
// the device's is the reference's, finite.
TEST(LightParameters, AtTheLongestDistancesAllowedTheCulledSolversStillGiveTheReferenceLight) {
  LightParameters longest_cutoff;
  longest_cutoff.cutoff_m = max_light_distance_m;
  LightParameters exact = longest_cutoff;
  exact.exact = true;
  LightParameters longest_cell;
  longest_cell.far_field_cell_m = max_light_distance_m;
  LightParameters near_field_alone;
  near_field_alone.far_field = false;
  const auto balls = shaded_stand(exact);
  const auto exact_light = ReferenceLightSolver(exact).solve(balls);
  const auto reference_cell_light = ReferenceLightSolver(longest_cell).solve(balls);
  expect_light(ReferenceLightSolver(longest_cutoff).solve(balls), exact_light, 1e-12, "reference, longest cut-off");
  expect_light(reference_cell_light, ReferenceLightSolver(near_field_alone).solve(balls), 1e-5,
               "reference, longest cell");
  const auto device = compute::opencl_backend_for_test();
  if (!device) GTEST_SKIP() << "no OpenCL device (the reference solvers were checked)";
  expect_light(make_light_solver(*device, longest_cutoff)->solve(balls), exact_light, 1e-4, "OpenCL, longest cut-off");
  expect_light(make_light_solver(*device, longest_cell)->solve(balls), reference_cell_light, 1e-4,
               "OpenCL, longest cell");
}

}  // namespace
}  // namespace heliostand
