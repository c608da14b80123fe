// The benchmarks' synthetic canopies (light/synthetic_canopy.hpp): the planting grid their ball count asks for, and
// a count beyond any memory refused at once.
#include <gtest/gtest.h>

#include <cstddef>
#include <stdexcept>

#include "light/synthetic_canopy.hpp"

namespace heliostand {
namespace {

// 250 balls at 100 a tree want 3 trees, which the square grid rounds up to 2 x 2 at 2.5 m.
TEST(SyntheticCanopy, TheBallCountAsksForASquareGridOfTrees) {
  const SyntheticCanopy canopy = make_synthetic_canopy(250, 1);
  EXPECT_EQ(canopy.tree_count, 4u);
  EXPECT_DOUBLE_EQ(canopy.plot_size_m, 5.0);
  ASSERT_EQ(canopy.balls.size(), 250u);
  ASSERT_EQ(canopy.tree_of_ball.size(), 250u);
  for (std::size_t k = 0; k < canopy.balls.size(); ++k) {
    EXPECT_EQ(canopy.tree_of_ball[k], int(k % 4)) << k;
    EXPECT_EQ(canopy.balls[k].radius, 0.3) << k;
    // within a crown: apex 12 m +-15 %, down a 6 m crown +-15 %
    EXPECT_GE(canopy.balls[k].centre.z, 12.0 * 0.85 - 6.0 * 1.15) << k;
    EXPECT_LE(canopy.balls[k].centre.z, 12.0 * 1.15) << k;
  }
  EXPECT_EQ(make_synthetic_canopy(1, 1).tree_count, 1u);
  EXPECT_EQ(make_synthetic_canopy(0, 1).tree_count, 1u);
}

// 2^59 balls are more than a vector of them can ever hold: refused before a single crown is drawn (drawing their
// 5.8e15 crowns first would run for days; counts near 2^64 wrapped to one tree).
TEST(SyntheticCanopy, ACountBeyondAnyMemoryIsRefusedAtOnce) {
  for (const std::size_t count : {std::size_t(1) << 59, ~std::size_t(0) - 50})
    EXPECT_THROW(make_synthetic_canopy(count, 1), std::length_error) << count;
}

}  // namespace
}  // namespace heliostand
