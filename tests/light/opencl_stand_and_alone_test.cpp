// The stand's light and every tree's open-grown light in one pass (LightSolver::solve_with_each_alone,
// cl/light.cl light_culled_and_alone) against the two solves it replaces, and the cases where it must decline.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "compute/opencl_context.hpp"
#include "compute/opencl_test_backend.hpp"
#include "light/celestial_sphere.hpp"
#include "light/opencl_light_solver.hpp"
#include "light/reference_light_solver.hpp"
#include "light_test_stands.hpp"

namespace heliostand {
namespace {

constexpr double plot_m = 8.0;
constexpr double column_m = 2.0;

// The stand's solver: culled, with a far field, on an 8 m plot.
LightParameters stand_parameters(bool periodic) {
  LightParameters p;
  p.exact = false;
  p.periodic = periodic;
  p.plot_x_max = p.plot_y_max = plot_m;
  p.cutoff_m = 1.5;  // part of each tree within the cut-off, part beyond it
  p.far_field_cell_m = 1.0;
  p.transmittance = 0.6;
  p.sky_scale = 0.7;  // the open-grown solver sees sky_scale 1: the one pass must use its B0, not the stand's
  return p;
}

// The open-grown solver as a run makes it (run/simulation.cpp): exact, open plot, sky_scale 1.
LightParameters alone_parameters(const LightParameters& stand) {
  LightParameters p = stand;
  p.exact = true;
  p.periodic = false;
  p.sky_scale = 1.0;
  return p;
}

// This machine's OpenCL device, called a CPU or a GPU. The one pass runs only on a CPU device, so the tests of its
// answers call the device a CPU whatever it is: the kernel is the same on every device.
std::optional<compute::OpenCLContext> device_as(cl_device_type type) {
  const auto backend = compute::opencl_backend_for_test();
  if (!backend) return std::nullopt;
  compute::OpenCLContext device = *backend->opencl();
  device.type = type;
  return device;
}

std::unique_ptr<LightSolver> solver_on(const compute::OpenCLContext& device, const LightParameters& parameters) {
  return std::make_unique<OpenCLLightSolver>(parameters, device);
}

struct Trees {
  std::vector<LeafBall> balls;
  std::vector<std::size_t> group_start{0};
};

// A random stand cut into trees: columns of 2 m x 2 m. On a torus the columns are shifted 1 m, so that the trees
// of the last row and column straddle the plot's edges; a tree's balls are given unwrapped, as a tree's are (the
// periodic solver wraps them). random_stand keeps every ray decision clear of float round-off, across the edges too.
Trees columns_of(const std::vector<LeafBall>& stand, bool straddle) {
  const int columns = int(plot_m / column_m);
  const double shift = straddle ? 1.0 : 0.0;
  auto column = [&](double x) { return int(std::floor(std::fmod(x + plot_m - shift, plot_m) / column_m)); };
  Trees trees;
  for (int cx = 0; cx < columns; ++cx)
    for (int cy = 0; cy < columns; ++cy) {
      for (LeafBall ball : stand) {
        if (column(ball.centre.x) != cx || column(ball.centre.y) != cy) continue;
        // the part of the last column below the shift lies past the plot's far edge
        if (ball.centre.x < shift) ball.centre.x += plot_m;
        if (ball.centre.y < shift) ball.centre.y += plot_m;
        trees.balls.push_back(ball);
      }
      trees.group_start.push_back(trees.balls.size());
    }
  return trees;
}

class StandAndAloneTest : public ::testing::TestWithParam<bool> {
 protected:
  void SetUp() override {
    device_ = device_as(CL_DEVICE_TYPE_CPU);
    if (!device_) GTEST_SKIP() << "no OpenCL device";
  }
  std::optional<compute::OpenCLContext> device_;
};

// One pass over `trees` against the two solves it replaces: the alone samples are light_each_alone's bit for bit, and
// on stands where no ray is decided within round-off (random_stand's) the stand's are light_culled's bit for bit too;
// both agree with the reference solver's two solves. Returns how much darker a ball is in the stand than alone, at
// most.
double expect_one_pass_gives_the_two_solves(const compute::OpenCLContext& device, const LightParameters& stand_p,
                                            const Trees& trees, const std::string& label) {
  const LightParameters alone_p = alone_parameters(stand_p);
  const auto stand_solver = solver_on(device, stand_p);
  const auto alone_solver = solver_on(device, alone_p);
  const auto both = stand_solver->solve_with_each_alone(trees.balls, trees.group_start, *alone_solver);
  if (!both) {
    ADD_FAILURE() << label << ": the OpenCL solver declined a stand it can light in one pass";
    return 0;
  }
  const auto stand = stand_solver->solve(trees.balls);
  const auto alone = alone_solver->solve_each_alone(trees.balls, trees.group_start);
  const auto reference_stand = ReferenceLightSolver(stand_p).solve(trees.balls);
  const auto reference_alone = ReferenceLightSolver(alone_p).solve_each_alone(trees.balls, trees.group_start);
  EXPECT_EQ(both->stand.size(), trees.balls.size()) << label;
  EXPECT_EQ(both->alone.size(), trees.balls.size()) << label;
  if (both->stand.size() != trees.balls.size() || both->alone.size() != trees.balls.size()) return 0;
  double darkest_gap = 0;
  for (std::size_t k = 0; k < trees.balls.size(); ++k) {
    EXPECT_EQ(both->alone[k].light, alone[k].light) << label << ", ball " << k;
    EXPECT_EQ(both->alone[k].vector, alone[k].vector) << label << ", ball " << k;
    EXPECT_EQ(both->stand[k].light, stand[k].light) << label << ", ball " << k;
    EXPECT_EQ(both->stand[k].vector, stand[k].vector) << label << ", ball " << k;
    EXPECT_NEAR(both->stand[k].light, reference_stand[k].light, 1e-4) << label << ", ball " << k;
    EXPECT_NEAR(both->alone[k].light, reference_alone[k].light, 1e-5) << label << ", ball " << k;
    darkest_gap = std::max(darkest_gap, both->alone[k].light - both->stand[k].light);
  }
  return darkest_gap;
}

TEST_P(StandAndAloneTest, OnePassGivesTheStandSolveAndEachTreeAlone) {
  const bool periodic = GetParam();
  const LightParameters stand_p = stand_parameters(periodic);
  const CelestialSphere sky(stand_p);
  const Trees trees = columns_of(testing::random_stand(220, plot_m, 0.15, 0.45, 5, sky, periodic), periodic);
  ASSERT_EQ(trees.group_start.size(), 17u);
  EXPECT_GT(expect_one_pass_gives_the_two_solves(*device_, stand_p, trees, periodic ? "periodic" : "open"), 0.2);
}

INSTANTIATE_TEST_SUITE_P(Plots, StandAndAloneTest, ::testing::Bool(),
                         [](const auto& info) { return std::string(info.param ? "Periodic" : "Open"); });

// The one pass reads a receiver's own tree in runs of eight balls, two runs at a time while sixteen remain, its last
// run reaching back over balls already shaded, and a tree of fewer than eight ball by ball (cl/light.cl,
// shade_by_own_tree). Trees of every size around those bounds, the receiver anywhere in its tree, and each tree
// partly within the 1.5 m cut-off and partly beyond it, must give the two solves' light.
TEST(StandAndAlone, TreesOfEverySizeAroundTheRunsOfEightGiveTheTwoSolves) {
  const auto device = device_as(CL_DEVICE_TYPE_CPU);
  if (!device) GTEST_SKIP() << "no OpenCL device";
  const LightParameters stand_p = stand_parameters(false);
  const CelestialSphere sky(stand_p);
  const std::vector<std::size_t> sizes{1, 2, 7, 8, 9, 15, 16, 17, 23, 24, 25, 31, 32, 33, 40};
  std::size_t total = 0;
  for (const std::size_t size : sizes) total += size;
  Trees trees;
  // a tree's balls scattered over the plot: some within the cut-off of a receiver of its tree, some beyond
  trees.balls = testing::random_stand(total, plot_m, 0.15, 0.45, 8, sky, false);
  for (const std::size_t size : sizes) trees.group_start.push_back(trees.group_start.back() + size);
  int within = 0, beyond = 0;
  for (std::size_t g = 0; g + 1 < trees.group_start.size(); ++g)
    for (auto i = trees.group_start[g]; i < trees.group_start[g + 1]; ++i)
      for (auto j = trees.group_start[g]; j < trees.group_start[g + 1]; ++j) {
        if (i == j) continue;
        const bool near = glm::length(trees.balls[i].centre - trees.balls[j].centre) <= stand_p.cutoff_m;
        within += near, beyond += !near;
      }
  EXPECT_GT(within, 100);  // own balls that shade both skies
  EXPECT_GT(beyond, 100);  // and own balls that shade the tree alone's only
  EXPECT_GT(expect_one_pass_gives_the_two_solves(*device, stand_p, trees, "trees of 1 to 40 balls"), 0.2);
}

// Where one pass would not give the two solves' answers, the solver says so and the caller solves twice.
TEST(StandAndAlone, DeclinedWhereOnePassWouldNotGiveTheSameLight) {
  const auto device = device_as(CL_DEVICE_TYPE_CPU);
  if (!device) GTEST_SKIP() << "no OpenCL device";
  const LightParameters stand_p = stand_parameters(true);
  const LightParameters alone_p = alone_parameters(stand_p);
  const CelestialSphere sky(stand_p);
  const Trees trees = columns_of(testing::random_stand(60, plot_m, 0.15, 0.45, 6, sky, true), true);
  auto declined = [&](const LightParameters& stand, const LightParameters& alone, const std::vector<LeafBall>& balls,
                      const std::vector<std::size_t>& groups) {
    return !solver_on(*device, stand)->solve_with_each_alone(balls, groups, *solver_on(*device, alone));
  };
  EXPECT_FALSE(declined(stand_p, alone_p, trees.balls, trees.group_start));  // the case that works
  LightParameters exact_stand = stand_p;
  exact_stand.exact = true;
  EXPECT_TRUE(declined(exact_stand, alone_p, trees.balls, trees.group_start)) << "stand solved exactly";
  LightParameters periodic_alone = alone_p;
  periodic_alone.periodic = true;
  EXPECT_TRUE(declined(stand_p, periodic_alone, trees.balls, trees.group_start)) << "trees alone on a torus";
  LightParameters culled_alone = alone_p;
  culled_alone.exact = false;
  EXPECT_TRUE(declined(stand_p, culled_alone, trees.balls, trees.group_start)) << "trees alone culled";
  LightParameters other_sky = alone_p;
  other_sky.sky_sectors = 16;
  EXPECT_TRUE(declined(stand_p, other_sky, trees.balls, trees.group_start)) << "another sky";
  LightParameters other_t = alone_p;
  other_t.transmittance = 0.5;
  EXPECT_TRUE(declined(stand_p, other_t, trees.balls, trees.group_start)) << "another transmittance";
  // a tree 6.6 m wide on the 8 m torus: an image of its ball comes within the 1.5 m cut-off of another of its balls
  const std::vector<LeafBall> wide{{{0.5, 4, 2}, 0.3}, {{7.1, 4, 2}, 0.3}};
  EXPECT_TRUE(declined(stand_p, alone_p, wide, {0, 2})) << "a tree wider than the plot less the cut-off";
  EXPECT_FALSE(declined(stand_p, alone_p, wide, {0, 1, 2})) << "the same balls as two trees";
  LightParameters open_stand = stand_p;
  open_stand.periodic = false;
  EXPECT_FALSE(declined(open_stand, alone_p, wide, {0, 2})) << "an open plot has no images";
  // the reference solver always solves twice
  ReferenceLightSolver reference(stand_p);
  EXPECT_FALSE(reference.solve_with_each_alone(trees.balls, trees.group_start, *solver_on(*device, alone_p)));
  EXPECT_THROW(solver_on(*device, stand_p)
                   ->solve_with_each_alone(trees.balls, std::vector<std::size_t>{0, 5}, *solver_on(*device, alone_p)),
               std::invalid_argument);
}

// On a GPU the one pass's two skies per work item cost more than a second launch (docs/performance.md "The one pass
// on a GPU"): the solver declines there, and only there, and the caller solves twice.
TEST(StandAndAlone, OnePassOnlyOnACpuDevice) {
  const LightParameters stand_p = stand_parameters(false);
  const LightParameters alone_p = alone_parameters(stand_p);
  const CelestialSphere sky(stand_p);
  const Trees trees = columns_of(testing::random_stand(60, plot_m, 0.15, 0.45, 6, sky, false), false);
  auto device = device_as(CL_DEVICE_TYPE_CPU);
  if (!device) GTEST_SKIP() << "no OpenCL device";
  for (const cl_device_type type : {CL_DEVICE_TYPE_CPU, CL_DEVICE_TYPE_GPU, CL_DEVICE_TYPE_ACCELERATOR}) {
    device->type = type;
    const auto both =
        solver_on(*device, stand_p)->solve_with_each_alone(trees.balls, trees.group_start, *solver_on(*device, alone_p));
    EXPECT_EQ(both.has_value(), type == CL_DEVICE_TYPE_CPU) << "device type " << type;
  }
}

}  // namespace
}  // namespace heliostand
