#include "geometry/compass_sector.hpp"

#include <gtest/gtest.h>

#include "coupling/crown_root_balance.hpp"
#include "roots/root_segment.hpp"

namespace heliostand {
namespace {

TEST(CompassSector, FortyFiveDegreeSectorsCountedCounterClockwiseFromEast) {
  EXPECT_EQ(compass_sector(0.0), 0);
  EXPECT_EQ(compass_sector(radians(44.9)), 0);
  EXPECT_EQ(compass_sector(radians(45.1)), 1);
  EXPECT_EQ(compass_sector(radians(100.0)), 2);
  EXPECT_EQ(compass_sector(radians(181.0)), 4);
  EXPECT_EQ(compass_sector(radians(359.9)), 7);
}

TEST(CompassSector, AnyAngleIsWrappedIntoOneTurn) {
  EXPECT_EQ(compass_sector(radians(-10.0)), 7);  // just south of east
  EXPECT_EQ(compass_sector(radians(360.0)), 0);
  EXPECT_EQ(compass_sector(radians(3 * 360.0 + 100.0)), 2);
  EXPECT_EQ(compass_sector(radians(-2 * 360.0 - 100.0)), 5);
  EXPECT_EQ(compass_sector(-1e-18), 7);  // −ε + 2π rounds to 2π: still the last sector, never an eighth
}

TEST(CompassSector, ADirectionFallsInTheSectorOfItsHorizontalPart) {
  EXPECT_EQ(compass_sector_of({1.0, 0.1, -0.3}), 0);
  EXPECT_EQ(compass_sector_of({0.0, 1.0, 0.0}), 2);
  EXPECT_EQ(compass_sector_of({-1.0, -0.01, 0.0}), 4);
  EXPECT_EQ(compass_sector_of({1.0, -0.01, 5.0}), 7);
}

// Crown and roots meet path by path only if both count the same sectors.
TEST(CompassSector, CrownAndRootPathsAreTheCompassSectors) {
  EXPECT_EQ(crown_path_count, compass_sector_count);
  EXPECT_EQ(roots::path_count, compass_sector_count);
}

}  // namespace
}  // namespace heliostand
