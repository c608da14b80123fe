// The far field's density with a margin around its sides, as the device sweep reads it (light/far_field_margin.hpp):
// the margin must hold what a lookup there gives by VoxelGrid's rules, and be wide enough for every lookup the
// sweep makes, or be left out where zeros would not equal those rules.
#include "light/far_field_margin.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "light/celestial_sphere.hpp"
#include "light/far_field.hpp"
#include "light/occluders.hpp"
#include "light_test_stands.hpp"

namespace heliostand {
namespace {

LightParameters far_field_parameters(bool periodic, double plot) {
  LightParameters p;
  p.exact = false;
  p.periodic = periodic;
  p.plot_x_max = p.plot_y_max = plot;
  p.cutoff_m = 2.0;
  p.far_field_cell_m = 0.5;
  p.sky_bands = 8;
  p.sky_sectors = 16;
  return p;
}

FarField far_field_of(const LightParameters& p, std::size_t balls, double size, std::uint64_t seed) {
  const CelestialSphere sky(p);
  const auto stand = testing::random_stand(balls, size, 0.2, 0.6, seed, sky, p.periodic);
  return FarField(make_occluder_set(stand, PlotTorus::from(p), 0), p, sky, false);
}

float padded_at(const FarField& far, const std::vector<float>& padded, int margin, int x, int y, int z) {
  const glm::ivec3 dims = far.grid().dims;
  const int row = dims.x + 2 * margin, rows = dims.y + 2 * margin;
  return padded.at((std::size_t(z) * rows + (y + margin)) * row + (x + margin));
}

TEST(FarFieldMargin, APeriodicGridsMarginHoldsTheCellsItWrapsTo) {
  const LightParameters p = far_field_parameters(true, 6.0);
  const FarField far = far_field_of(p, 200, 6.0, 3);
  const int margin = sweep_margin_cells(far, CelestialSphere(p).patches());
  ASSERT_GT(margin, 0);
  const std::vector<float> padded = density_with_margin(far, margin);
  const VoxelGrid& grid = far.grid();
  ASSERT_EQ(padded.size(), std::size_t(grid.dims.x + 2 * margin) * (grid.dims.y + 2 * margin) * grid.dims.z);
  int foliage_in_margin = 0;
  for (int z = 0; z < grid.dims.z; ++z)
    for (int y = -margin; y < grid.dims.y + margin; ++y)
      for (int x = -margin; x < grid.dims.x + margin; ++x) {
        const double sigma = far.density()[grid.index(wrap_cell(x, grid.dims.x), wrap_cell(y, grid.dims.y), z)];
        ASSERT_EQ(padded_at(far, padded, margin, x, y, z), static_cast<float>(sigma)) << x << " " << y << " " << z;
        const bool inside = x >= 0 && y >= 0 && x < grid.dims.x && y < grid.dims.y;
        foliage_in_margin += !inside && sigma > 0;
      }
  EXPECT_GT(foliage_in_margin, 0);  // the wrap really brings foliage into the margin
}

TEST(FarFieldMargin, AnOpenGridsMarginHoldsZerosAndItsCellsTheDensity) {
  const LightParameters p = far_field_parameters(false, 6.0);
  const FarField far = far_field_of(p, 200, 6.0, 4);
  const int margin = sweep_margin_cells(far, CelestialSphere(p).patches());
  ASSERT_GT(margin, 0);  // the grid's own two cells of margin keep its outermost cells empty
  const std::vector<float> padded = density_with_margin(far, margin);
  const VoxelGrid& grid = far.grid();
  for (int z = 0; z < grid.dims.z; ++z)
    for (int y = -margin; y < grid.dims.y + margin; ++y)
      for (int x = -margin; x < grid.dims.x + margin; ++x) {
        const bool inside = x >= 0 && y >= 0 && x < grid.dims.x && y < grid.dims.y;
        const float expected = inside ? static_cast<float>(far.density()[grid.index(x, y, z)]) : 0.0f;
        ASSERT_EQ(padded_at(far, padded, margin, x, y, z), expected) << x << " " << y << " " << z;
      }
}

// The sweep (cl/far_field.cl) looks up the density at start_distance() + (k + 1/2) step along a patch's direction,
// k < ceil(reach / cell), step = reach / ceil(...), reach = the path to the next layer's mid-plane; a lookup's
// columns run from floor(shift) to floor(shift) + 1 cells from the lane's own.
TEST(FarFieldMargin, EveryLookupOfTheSweepLandsWithinTheMargin) {
  for (const bool periodic : {false, true}) {
    const LightParameters p = far_field_parameters(periodic, 6.0);
    const CelestialSphere sky(p);
    const FarField far = far_field_of(p, 200, 6.0, 5);
    const int margin = sweep_margin_cells(far, sky.patches());
    ASSERT_GT(margin, 0);
    const VoxelGrid& grid = far.grid();
    const double cell = std::min({grid.cell.x, grid.cell.y, grid.cell.z});
    for (const auto& patch : sky.patches()) {
      const glm::dvec3& n = patch.direction;
      const double reach = grid.cell.z / std::abs(n.z);
      const int samples = std::max(1, static_cast<int>(std::ceil(reach / cell - 1e-6)));
      for (int k = 0; k < samples; ++k) {
        const double along = far.start_distance() + (k + 0.5) * reach / samples;
        for (const double shift : {along * n.x / grid.cell.x, along * n.y / grid.cell.y}) {
          EXPECT_GE(std::floor(shift), -margin) << "band " << patch.band << " sector " << patch.sector;
          EXPECT_LE(std::floor(shift) + 1, margin) << "band " << patch.band << " sector " << patch.sector;
        }
      }
    }
  }
}

// A stand too big for the table's budget gets cells coarser than the grid's two cells of margin (FarField's
// grid_around): then balls deposit into the outermost cells, where zeros in the margin would differ from the
// clamp to those cells, and the sweep gets no margin.
TEST(FarFieldMargin, AnOpenGridWhoseOutermostCellsHoldFoliageGetsNone) {
  LightParameters p = far_field_parameters(false, 16.0);
  p.far_field_cell_m = 1.0;
  p.far_field_table_mb = 1;  // 1 953 cells for 128 patches: cells of ~1.8 m on this stand
  const FarField far = far_field_of(p, 400, 16.0, 6);
  ASSERT_GT(far.grid().cell.x, 1.5);
  const VoxelGrid& grid = far.grid();
  double outermost = 0;
  for (int z = 0; z < grid.dims.z; ++z)
    for (int y = 0; y < grid.dims.y; ++y)
      for (int x = 0; x < grid.dims.x; ++x)
        if (x == 0 || y == 0 || x == grid.dims.x - 1 || y == grid.dims.y - 1)
          outermost += far.density()[grid.index(x, y, z)];
  ASSERT_GT(outermost, 0.0);
  EXPECT_EQ(sweep_margin_cells(far, CelestialSphere(p).patches()), 0);
  // the same grid on a torus wraps, whatever its outermost cells hold
  p.periodic = true;
  EXPECT_GT(sweep_margin_cells(far_field_of(p, 400, 16.0, 6), CelestialSphere(p).patches()), 0);
}

}  // namespace
}  // namespace heliostand
