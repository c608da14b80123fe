// Planting rows found from stem positions: the direction from the nearest neighbours, the rows as separated bands
// across it, and a clear refusal where there are no rows.
#include "geometry/planting_rows.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/angles.hpp"
#include "rng/random_stream.hpp"

namespace heliostand {
namespace {

using ::testing::HasSubstr;

struct Planting {
  std::vector<glm::dvec2> positions;
  std::vector<int> row;  // the row each tree was planted in, 0 = the first across the rows
};

// `rows` rows of `per_row` trees, `in_row` m apart within a row and `between` m between rows, the rows running at
// `azimuth_deg`, each position off its planting spot by up to `jitter` m in x and y.
Planting planted(int rows, int per_row, double in_row, double between, double azimuth_deg, double jitter) {
  RandomStream random(11);
  const glm::dvec2 along{std::cos(radians(azimuth_deg)), std::sin(radians(azimuth_deg))};
  const glm::dvec2 across{-along.y, along.x};
  Planting planting;
  for (int r = 0; r < rows; ++r)
    for (int k = 0; k < per_row; ++k) {
      const glm::dvec2 noise{random.uniform(-jitter, jitter), random.uniform(-jitter, jitter)};
      planting.positions.push_back(glm::dvec2(5, 5) + along * (k * in_row) + across * (r * between) + noise);
      planting.row.push_back(r);
    }
  return planting;
}

TEST(PlantingRows, FindsTheDirectionAndRowsOfARectangularPlanting) {
  // 1.5 m within rows, 3 m between them, rows running 20° north of east, positions off by up to 0.2 m.
  const Planting planting = planted(6, 12, 1.5, 3.0, 20.0, 0.2);
  const PlantingRowsFound found = find_planting_rows(planting.positions, std::nullopt, 1.0);
  ASSERT_TRUE(found.rows) << found.problem;
  EXPECT_NEAR(found.rows->azimuth_deg, 20.0, 1.0);
  EXPECT_EQ(found.rows->count, 6);
  EXPECT_EQ(found.rows->row_of, planting.row);  // numbered from the south: the rows run within 45° of east–west
}

TEST(PlantingRows, NorthSouthRowsAreNumberedFromTheWest) {
  const Planting planting = planted(4, 10, 1.5, 3.0, 90.0, 0.1);
  const PlantingRowsFound found = find_planting_rows(planting.positions, std::nullopt, 1.0);
  ASSERT_TRUE(found.rows) << found.problem;
  EXPECT_NEAR(found.rows->azimuth_deg, 90.0, 1.0);
  // The helper lays the rows out towards the west (across = along turned left); the westernmost is row 0.
  for (std::size_t i = 0; i < planting.row.size(); ++i) EXPECT_EQ(found.rows->row_of[i], 3 - planting.row[i]) << i;
}

TEST(PlantingRows, ASquarePlantingNeedsItsDirectionGiven) {
  const Planting planting = planted(5, 5, 2.0, 2.0, 0.0, 0.1);
  const PlantingRowsFound unknown = find_planting_rows(planting.positions, std::nullopt, 1.0);
  EXPECT_FALSE(unknown.rows);
  EXPECT_THAT(unknown.problem, HasSubstr("no row direction"));
  EXPECT_THAT(unknown.problem, HasSubstr("give row_azimuth_deg"));
  const PlantingRowsFound given = find_planting_rows(planting.positions, 0.0, 1.0);
  ASSERT_TRUE(given.rows) << given.problem;
  EXPECT_EQ(given.rows->row_of, planting.row);
  // The same rows, called by the opposite direction, are numbered the same way.
  EXPECT_EQ(find_planting_rows(planting.positions, 180.0, 1.0).rows->row_of, planting.row);
}

TEST(PlantingRows, ScatteredTreesAreNotInRows) {
  RandomStream random(5);
  std::vector<glm::dvec2> scattered;
  for (int i = 0; i < 60; ++i) scattered.push_back({random.uniform(0, 20), random.uniform(0, 20)});
  for (double azimuth : {0.0, 37.0, 90.0}) {
    const PlantingRowsFound found = find_planting_rows(scattered, azimuth, 1.0);
    EXPECT_FALSE(found.rows) << azimuth;
    EXPECT_THAT(found.problem, HasSubstr("are not in rows")) << azimuth;
  }
}

TEST(PlantingRows, OneRowIsNoRowStructure) {
  const Planting planting = planted(1, 10, 2.0, 3.0, 0.0, 0.0);
  const PlantingRowsFound found = find_planting_rows(planting.positions, std::nullopt, 1.0);
  EXPECT_FALSE(found.rows);
  EXPECT_THAT(found.problem, HasSubstr("single row"));
}

TEST(PlantingRows, RowsCloserThanTheToleranceAreNotSeparated) {
  // Rows 1 m apart: bands up to 1 m wide run into the next row. Bands up to 0.4 m wide find them.
  const Planting planting = planted(4, 10, 0.8, 1.0, 0.0, 0.1);
  EXPECT_FALSE(find_planting_rows(planting.positions, 0.0, 1.0).rows);
  const PlantingRowsFound found = find_planting_rows(planting.positions, 0.0, 0.4);
  ASSERT_TRUE(found.rows) << found.problem;
  EXPECT_EQ(found.rows->row_of, planting.row);
}

}  // namespace
}  // namespace heliostand
