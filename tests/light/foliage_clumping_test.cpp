// The clumping index of a far-field cell against hand-computed gap fractions.
#include "light/foliage_clumping.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "core/parallel_for.hpp"
#include "rng/random_stream.hpp"

namespace heliostand {
namespace {

constexpr double pi = std::numbers::pi;

VoxelGrid three_cells_across() {
  VoxelGrid grid;
  grid.dims = {3, 3, 3};
  return grid;  // 1 m cells from the origin: the middle cell is (1, 1, 1)
}

double middle_clumping(int stacked_balls, double t) {
  const std::vector<LeafBall> balls(stacked_balls, LeafBall{{1.5, 1.5, 1.5}, 0.2});
  const VoxelGrid grid = three_cells_across();
  return cell_clumping_index(make_occluder_set(balls, PlotTorus{}, 0), grid, t)[grid.index(1, 1, 1)];
}

TEST(FoliageClumping, BallsInOnePlaceLetThroughWhatOneBallWould) {
  // k balls at one centre: along every axis a fraction p of the face keeps t^k, the rest 1; a random medium of
  // the same density would keep exp(-(1 - t) k p). Omega = ln(1 - (1 - t^k) p) / (-(1 - t) k p): ~0.5 for 4.
  const double t = 0.5, p = pi * 0.2 * 0.2;
  for (int k : {2, 4, 8}) {
    const double expected = -std::log(1 - (1 - std::pow(t, k)) * p) / ((1 - t) * k * p);
    EXPECT_NEAR(middle_clumping(k, t), expected, 0.01) << k << " balls";
  }
  EXPECT_LT(middle_clumping(4, t), 0.55);
}

TEST(FoliageClumping, ALoneBallIsRegularNotClumped) {
  // one disc per face: 1 - (1 - t) p kept, below the random exp(-(1 - t) p), so Omega is a little above 1
  const double t = 0.5, p = pi * 0.2 * 0.2;
  EXPECT_NEAR(middle_clumping(1, t), -std::log(1 - (1 - t) * p) / ((1 - t) * p), 1e-3);
  EXPECT_GT(middle_clumping(1, t), 1.0);
}

TEST(FoliageClumping, EmptyCellsAndClearBallsKeepTheirDensity) {
  const std::vector<LeafBall> balls(4, LeafBall{{1.5, 1.5, 1.5}, 0.2});
  const VoxelGrid grid = three_cells_across();
  const auto occluders = make_occluder_set(balls, PlotTorus{}, 0);
  EXPECT_EQ(cell_clumping_index(occluders, grid, 0.5)[grid.index(0, 0, 0)], 1.0);  // no shadow falls there
  for (double omega : cell_clumping_index(occluders, grid, 1.0)) EXPECT_EQ(omega, 1.0);  // t = 1: nothing shades
}

// The slabs are rasterised on the worker threads: a canopy spread through a periodic grid of 7 x 6 x 5 cells (slabs
// that do not share out evenly, balls across the plot's edges) gets the same index in every cell, bit for bit, on
// 1, 2, 3 and 8 threads, and its balls do clump somewhere.
TEST(FoliageClumping, TheSameIndexOnAnyNumberOfThreads) {
  RandomStream random(11, {3});
  std::vector<LeafBall> balls;
  for (int k = 0; k < 400; ++k)
    balls.push_back({{random.uniform(0, 7), random.uniform(0, 6), random.uniform(0, 5)}, random.uniform(0.1, 0.4)});
  VoxelGrid grid;
  grid.dims = {7, 6, 5};
  grid.periodic = true;
  PlotTorus torus;
  torus.periodic = true;
  torus.size = {7, 6};
  const auto occluders = make_occluder_set(balls, torus, 0);
  set_worker_threads(1);
  const std::vector<double> in_order = cell_clumping_index(occluders, grid, 0.5);
  for (unsigned threads : {2u, 3u, 8u}) {
    set_worker_threads(threads);
    EXPECT_EQ(cell_clumping_index(occluders, grid, 0.5), in_order) << threads << " threads";
  }
  set_worker_threads(0);
  double lowest = 1;
  for (double omega : in_order) lowest = std::min(lowest, omega);
  EXPECT_LT(lowest, 0.95);
}

}  // namespace
}  // namespace heliostand
