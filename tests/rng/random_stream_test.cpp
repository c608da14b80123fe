#include "rng/random_stream.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace heliostand {

TEST(RandomStream, SameSeedAndTagsGiveSameSequence) {
  RandomStream a(42, {7, 2030}), b(42, {7, 2030});
  for (int i = 0; i < 100; ++i) EXPECT_EQ(a.next_u64(), b.next_u64());
}

TEST(RandomStream, DifferentTagsGiveDifferentSequences) {
  RandomStream a(42, {7, 2030}), b(42, {8, 2030}), c(42, {2030, 7});
  EXPECT_NE(a.next_u64(), b.next_u64());
  RandomStream a2(42, {7, 2030});
  EXPECT_NE(a2.next_u64(), c.next_u64()) << "tag order must matter";
}

TEST(RandomStream, UniformStaysInRangeWithRightMean) {
  RandomStream r(1);
  double sum = 0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    const double u = r.symmetric();
    ASSERT_GE(u, -1.0);
    ASSERT_LT(u, 1.0);
    sum += u;
  }
  EXPECT_NEAR(sum / n, 0.0, 0.01);
}

TEST(RandomStream, NormalHasRequestedMoments) {
  RandomStream r(3);
  double sum = 0, sum2 = 0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    const double x = r.normal(5.0, 2.0);
    sum += x;
    sum2 += x * x;
  }
  const double mean = sum / n;
  EXPECT_NEAR(mean, 5.0, 0.03);
  EXPECT_NEAR(std::sqrt(sum2 / n - mean * mean), 2.0, 0.03);
}

}  // namespace heliostand
