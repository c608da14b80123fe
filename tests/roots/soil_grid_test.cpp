#include "roots/soil_grid.hpp"

#include <gtest/gtest.h>

namespace heliostand::roots {
namespace {

// 2 × 2 × 2 voxels of 1 m: vertices at x, y ∈ {0, 1, 2}, z ∈ {−2, −1, 0}; the surface is z = 0.
SoilGrid small_grid(double moisture = 1.0) { return SoilGrid({{0.0, 0.0, -2.0}, 1.0, {2, 2, 2}}, moisture, 0.5); }

TEST(SoilGrid, GeometryOfVerticesAndSurface) {
  const SoilGrid soil = small_grid();
  EXPECT_EQ(soil.vertex_count(), 27u);
  EXPECT_DOUBLE_EQ(soil.surface_z(), 0.0);
  EXPECT_EQ(soil.vertex_position(2, 1, 0), glm::dvec3(2.0, 1.0, -2.0));
  EXPECT_TRUE(soil.contains({1.0, 1.0, -1.0}));
  EXPECT_FALSE(soil.contains({1.0, 1.0, 0.5}));
}

TEST(SoilGrid, RejectsEmptyOrFlatGrids) {
  EXPECT_THROW(SoilGrid({{0, 0, 0}, 0.0, {2, 2, 2}}, 1, 1), std::invalid_argument);
  EXPECT_THROW(SoilGrid({{0, 0, 0}, 1.0, {2, 0, 2}}, 1, 1), std::invalid_argument);
}

TEST(SoilGrid, TrilinearInterpolationBetweenVertices) {
  SoilGrid soil = small_grid(0.0);
  // One voxel's corners 0..7 get values 1..8 (corner c = i + 2j + 4k).
  for (int c = 0; c < 8; ++c) soil.at(SoilField::moisture, c & 1, (c >> 1) & 1, (c >> 2) & 1) = c + 1;
  EXPECT_DOUBLE_EQ(soil.moisture({0.0, 0.0, -2.0}), 1.0);
  EXPECT_DOUBLE_EQ(soil.moisture({1.0, 1.0, -1.0}), 8.0);
  EXPECT_DOUBLE_EQ(soil.moisture({0.5, 0.5, -1.5}), 4.5);  // the mean of 1..8 at the voxel centre
  // Along x on the bottom-front edge: 1 → 2.
  EXPECT_DOUBLE_EQ(soil.moisture({0.25, 0.0, -2.0}), 1.25);
  // f = (0.5, 0, 0.5): mean of corners 0,1,4,5 = (1+2+5+6)/4.
  EXPECT_DOUBLE_EQ(soil.moisture({0.5, 0.0, -1.5}), 3.5);
}

TEST(SoilGrid, PointsOutsideReadTheNearestBoundaryValue) {
  SoilGrid soil = small_grid();
  soil.fill_gradient(SoilField::moisture, 0, 1.0, 0.0);
  EXPECT_DOUBLE_EQ(soil.moisture({-5.0, 1.0, -1.0}), 1.0);
  EXPECT_DOUBLE_EQ(soil.moisture({9.0, 1.0, -1.0}), 0.0);
  EXPECT_DOUBLE_EQ(soil.moisture({0.5, 1.0, 3.0}), 0.75);  // above ground: the surface value
}

TEST(SoilGrid, LinearGradientAlongAnAxis) {
  SoilGrid soil = small_grid();
  soil.fill_gradient(SoilField::moisture, 0, 1.0, 0.0);
  EXPECT_DOUBLE_EQ(soil.at(SoilField::moisture, 0, 2, 1), 1.0);
  EXPECT_DOUBLE_EQ(soil.at(SoilField::moisture, 1, 0, 0), 0.5);
  EXPECT_DOUBLE_EQ(soil.at(SoilField::moisture, 2, 1, 2), 0.0);
  EXPECT_DOUBLE_EQ(soil.moisture({1.5, 0.3, -0.7}), 0.25);
  soil.fill_gradient(SoilField::nutrient, 2, 0.2, 1.0);  // richer toward the surface
  EXPECT_DOUBLE_EQ(soil.nutrient({1.0, 1.0, -1.0}), 0.6);
  EXPECT_THROW(soil.fill_gradient(SoilField::nutrient, 3, 0, 1), std::invalid_argument);
}

TEST(SoilGrid, LayersByDepth) {
  SoilGrid soil = small_grid();
  soil.fill_layers(SoilField::moisture, {0.5, 1.5}, {0.9, 0.4});
  EXPECT_DOUBLE_EQ(soil.at(SoilField::moisture, 0, 0, 2), 0.9);  // depth 0
  EXPECT_DOUBLE_EQ(soil.at(SoilField::moisture, 0, 0, 1), 0.4);  // depth 1
  EXPECT_DOUBLE_EQ(soil.at(SoilField::moisture, 0, 0, 0), 0.4);  // depth 2: below the last bottom
  EXPECT_THROW(soil.fill_layers(SoilField::moisture, {1.0, 0.5}, {1, 2}), std::invalid_argument);
  EXPECT_THROW(soil.fill_layers(SoilField::moisture, {1.0}, {1, 2}), std::invalid_argument);
}

TEST(SoilGrid, DepletionTakesTrilinearSharesAndNeverGoesNegative) {
  SoilGrid soil = small_grid();
  EXPECT_DOUBLE_EQ(soil.deplete(SoilField::moisture, {1.0, 1.0, -1.0}, 0.1), 0.1);  // on a vertex
  EXPECT_DOUBLE_EQ(soil.at(SoilField::moisture, 1, 1, 1), 0.9);
  EXPECT_DOUBLE_EQ(soil.at(SoilField::moisture, 0, 1, 1), 1.0);
  // At a voxel centre each of the 8 corners gives 1/8 of the fraction of its own value.
  EXPECT_NEAR(soil.deplete(SoilField::moisture, {1.5, 1.5, -0.5}, 0.8), 0.1 * (7 * 1.0 + 0.9), 1e-12);
  EXPECT_DOUBLE_EQ(soil.at(SoilField::moisture, 2, 2, 2), 0.9);
  EXPECT_DOUBLE_EQ(soil.at(SoilField::moisture, 1, 1, 1), 0.9 * 0.9);
  soil.deplete(SoilField::moisture, {0.0, 0.0, -2.0}, 50.0);
  EXPECT_DOUBLE_EQ(soil.at(SoilField::moisture, 0, 0, 0), 0.0);
  EXPECT_DOUBLE_EQ(soil.nutrient({0.0, 0.0, -2.0}), 0.5);  // the other field is untouched
}

TEST(SoilGrid, RechargeMovesBackTowardEachVertexCapacity) {
  SoilGrid soil = small_grid();
  soil.fill_gradient(SoilField::moisture, 0, 1.0, 0.0);
  soil.at(SoilField::moisture, 0, 0, 0) = 0.5;  // capacity 1.0
  soil.at(SoilField::moisture, 1, 0, 0) = 0.1;  // capacity 0.5
  SoilRecharge recharge{.moisture_rate = 0.8, .nutrient_rate = 0.0};
  soil.recharge(recharge);
  EXPECT_DOUBLE_EQ(soil.at(SoilField::moisture, 0, 0, 0), 0.9);
  EXPECT_DOUBLE_EQ(soil.at(SoilField::moisture, 1, 0, 0), 0.42);
  EXPECT_DOUBLE_EQ(soil.at(SoilField::moisture, 2, 0, 0), 0.0);  // a dry vertex stays dry
  // Two years at once equal two single years.
  SoilGrid once = soil, twice = soil;
  once.recharge(recharge, 2.0);
  twice.recharge(recharge);
  twice.recharge(recharge);
  EXPECT_NEAR(once.at(SoilField::moisture, 1, 0, 0), twice.at(SoilField::moisture, 1, 0, 0), 1e-15);
  EXPECT_DOUBLE_EQ(soil.nutrient({1, 1, -1}), 0.5);
}

}  // namespace
}  // namespace heliostand::roots
