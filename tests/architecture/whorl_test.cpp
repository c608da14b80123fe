#include "architecture/whorl.hpp"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "geometry/angles.hpp"

namespace heliostand {
namespace {

TEST(Whorl, HeavySnowProvenanceMeanIsEq3) {
  // 20.40 × 0.38 - 3.188 = 7.752 - 3.188 = 4.564
  EXPECT_NEAR(mean_branches_per_whorl(SpeciesParameters{}), 4.564, 1e-12);
}

TEST(Whorl, DrawnSizesAreFourOrFiveWithEq3Mean) {
  const SpeciesParameters species;
  RandomStream random(11, {1});
  const int draws = 40000;
  double sum = 0.0;
  for (int i = 0; i < draws; ++i) {
    const int n = draw_whorl_size(species, random);
    ASSERT_TRUE(n == 4 || n == 5) << n;
    sum += n;
  }
  // Standard error of the mean: sqrt(0.564 × 0.436 / 40000) = 0.0025; 0.01 is 4 standard errors.
  EXPECT_NEAR(sum / draws, 4.564, 0.01);
}

TEST(Whorl, AzimuthsWithoutJitterAreEvenlySpaced) {
  RandomStream random(3);
  auto azimuths = whorl_azimuths(5, 0.0, random);
  ASSERT_EQ(azimuths.size(), 5u);
  std::sort(azimuths.begin(), azimuths.end());
  for (int i = 1; i < 5; ++i) EXPECT_NEAR(azimuths[i] - azimuths[i - 1], 2.0 * pi / 5.0, 1e-9);
}

TEST(Whorl, JitteredAzimuthsStayWithinHalfTheJitterOfEvenSpacing) {
  RandomStream random(5);
  for (int trial = 0; trial < 200; ++trial) {
    auto azimuths = whorl_azimuths(4, 0.3, random);
    std::sort(azimuths.begin(), azimuths.end());
    bool any_uneven = false;
    for (int i = 0; i < 4; ++i) {
      ASSERT_GE(azimuths[i], 0.0);
      ASSERT_LT(azimuths[i], 2.0 * pi);
      const double gap = i == 0 ? azimuths[0] + 2.0 * pi - azimuths[3] : azimuths[i] - azimuths[i - 1];
      // Spacing 90°, each branch moved by at most ± 0.3 × 90° / 2 = 13.5°, so a gap is 90° ± 27°.
      EXPECT_GE(gap, radians(63.0) - 1e-9);
      EXPECT_LE(gap, radians(117.0) + 1e-9);
      any_uneven = any_uneven || std::abs(gap - pi / 2.0) > 1e-6;
    }
    EXPECT_TRUE(any_uneven);
  }
}

}  // namespace
}  // namespace heliostand
