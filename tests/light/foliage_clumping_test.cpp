// The clumping index of a far-field cell against hand-computed gap fractions.
#include "light/foliage_clumping.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "core/parallel_for.hpp"
#include "geometry/angles.hpp"
#include "rng/random_stream.hpp"

namespace heliostand {
namespace {

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


// The definition the rasteriser must keep (docs/model.md, the clumping index): each ball's disc rasterised pixel by
// pixel on the whole face of its slab (a pixel shaded when its centre lies within the radius, wrapped on a periodic
// side, its count capped at 255), and each cell's pixels summed row by row. Slow, and written for clarity only.
std::vector<double> clumping_pixel_by_pixel(const OccluderSet& occluders, const VoxelGrid& grid, double t) {
  std::vector<double> omega(grid.cell_count(), 1.0);
  double mean_radius = 0;
  for (std::size_t k = 0; k < occluders.ball_count; ++k) mean_radius += occluders.radii[k] / occluders.ball_count;
  const double cell = std::min({grid.cell.x, grid.cell.y, grid.cell.z});
  const double largest_face =
      std::max({double(grid.dims.x) * grid.dims.y, double(grid.dims.y) * grid.dims.z, double(grid.dims.z) * grid.dims.x});
  const int P = static_cast<int>(std::clamp(
      std::min(std::ceil(3.0 * cell / mean_radius), std::floor(std::sqrt(double(1 << 26) / largest_face))), 4.0, 32.0));
  std::vector<double> log_gap(grid.cell_count(), 0.0), hits(grid.cell_count(), 0.0);
  auto slab_of = [&](const glm::dvec3& centre, int axis) {
    const int i = static_cast<int>(std::floor((centre[axis] - grid.origin[axis]) / grid.cell[axis]));
    return grid.periodic && axis < 2 ? wrap_cell(i, grid.dims[axis]) : std::clamp(i, 0, grid.dims[axis] - 1);
  };
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3, nu = grid.dims[u] * P, nv = grid.dims[v] * P;
    const double pu = grid.cell[u] / P, pv = grid.cell[v] / P;
    for (int s = 0; s < grid.dims[axis]; ++s) {
      std::vector<int> shadows(std::size_t(nu) * nv, 0);
      for (std::size_t k = 0; k < occluders.ball_count; ++k) {
        const glm::dvec3& c = occluders.centres[k];
        if (slab_of(c, axis) != s) continue;
        const double cu = (c[u] - grid.origin[u]) / pu - 0.5, cv = (c[v] - grid.origin[v]) / pv - 0.5;
        const double r = occluders.radii[k];
        for (int j = int(std::ceil(cv - r / pv)); j <= int(std::floor(cv + r / pv)); ++j)
          for (int i = int(std::ceil(cu - r / pu)); i <= int(std::floor(cu + r / pu)); ++i) {
            const double du = (i - cu) * pu, dv = (j - cv) * pv;
            if (du * du + dv * dv > r * r) continue;
            const int iu = grid.periodic && u < 2 ? wrap_cell(i, nu) : i;
            const int iv = grid.periodic && v < 2 ? wrap_cell(j, nv) : j;
            if (iu >= 0 && iu < nu && iv >= 0 && iv < nv) shadows[std::size_t(iv) * nu + iu] += 1;
          }
      }
      for (int b = 0; b < grid.dims[v]; ++b)
        for (int a = 0; a < grid.dims[u]; ++a) {
          double gap = 0, count = 0;
          for (int j = b * P; j < (b + 1) * P; ++j)
            for (int i = a * P; i < (a + 1) * P; ++i) {
              const int n = std::min(shadows[std::size_t(j) * nu + i], 255);
              gap += std::pow(t, n);
              count += n;
            }
          if (count == 0) continue;
          int at[3];
          at[axis] = s, at[u] = a, at[v] = b;
          log_gap[grid.index(at[0], at[1], at[2])] -= std::log(gap / (P * P));
          hits[grid.index(at[0], at[1], at[2])] += count / (P * P);
        }
    }
  }
  for (std::size_t c = 0; c < omega.size(); ++c)
    if (hits[c] > 0) omega[c] = log_gap[c] / ((1.0 - t) * hits[c]);
  return omega;
}

// The rasteriser works band by band and row span by row span (light/foliage_clumping.cpp); on small grids, periodic
// or not, with balls beyond the grid and discs wider than a cell or than the whole face (wrapped onto it more than
// once), it gives the pixel-by-pixel index bit for bit.
TEST(FoliageClumping, TheIndexOfEveryPixelTestedOneByOneBitForBit) {
  int periodic_wide_discs = 0;
  for (int trial = 0; trial < 60; ++trial) {
    RandomStream random(trial, {7});
    VoxelGrid grid;
    grid.dims = {1 + int(random.uniform(0, 6)), 1 + int(random.uniform(0, 6)), 1 + int(random.uniform(0, 4))};
    grid.cell = glm::dvec3(random.uniform(0.3, 1.5));
    if (trial % 3 == 0) grid.cell = {random.uniform(0.3, 1.5), random.uniform(0.3, 1.5), random.uniform(0.3, 1.5)};
    grid.origin = {random.uniform(-5, 5), random.uniform(-5, 5), random.uniform(-5, 5)};
    grid.periodic = trial % 2 == 0;
    PlotTorus torus;
    torus.periodic = grid.periodic;
    torus.origin = {grid.origin.x, grid.origin.y};
    torus.size = {grid.dims.x * grid.cell.x, grid.dims.y * grid.cell.y};
    const double largest_radius = trial % 4 == 0 ? 3.0 : 0.6;
    std::vector<LeafBall> balls;
    for (int k = 0, n = 1 + int(random.uniform(0, 150)); k < n; ++k) {
      const glm::dvec3 at{random.uniform(-1, torus.size.x + 1), random.uniform(-1, torus.size.y + 1),
                          random.uniform(-1, grid.dims.z * grid.cell.z + 1)};
      balls.push_back({grid.origin + at, random.uniform(0.02, largest_radius)});
    }
    if (grid.periodic && largest_radius > 2 * std::min(torus.size.x, torus.size.y)) ++periodic_wide_discs;
    const auto occluders = make_occluder_set(balls, torus, 0);
    const double t = random.uniform(0.1, 0.9);
    const std::vector<double> expected = clumping_pixel_by_pixel(occluders, grid, t);
    const std::vector<double> omega = cell_clumping_index(occluders, grid, t);
    ASSERT_EQ(omega.size(), expected.size());
    EXPECT_EQ(std::memcmp(omega.data(), expected.data(), omega.size() * sizeof(double)), 0) << "trial " << trial;
  }
  EXPECT_GT(periodic_wide_discs, 0);  // the trials do wrap discs around a whole periodic face
}

// Discs whose edge meets a pixel centre at round-off (found by a search over one ball in 1 m cells): a row's span
// from the square root alone is one pixel too wide or too narrow there, and only the test at its ends gets them right.
TEST(FoliageClumping, DiscEdgesOnAPixelCentreAsThePixelTestDecides) {
  const VoxelGrid grid = three_cells_across();
  const LeafBall edges[] = {{{1.375, 1.453125, 1.5}, 0.046874999999999986},
                            {{2.0208333333333335, 1.3541666666666665, 1.5}, 0.125},
                            {{1.828125, 1.796875, 1.5}, 0.062499999999999986},
                            {{2.0, 1.5, 1.5}, 0.4999999999999999},
                            {{1.25, 2.0833333333333335, 1.5}, 0.5000000000000001}};
  for (const LeafBall& ball : edges) {
    const auto occluders = make_occluder_set(std::vector<LeafBall>{ball}, PlotTorus{}, 0);
    const std::vector<double> expected = clumping_pixel_by_pixel(occluders, grid, 0.5);
    const std::vector<double> omega = cell_clumping_index(occluders, grid, 0.5);
    EXPECT_EQ(std::memcmp(omega.data(), expected.data(), omega.size() * sizeof(double)), 0) << ball.radius;
  }
}

}  // namespace
}  // namespace heliostand
