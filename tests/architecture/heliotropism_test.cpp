// Seed 000's heliotropism (Fig. 4) and death threshold, against hand-computed rotations.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "architecture/death_threshold.hpp"
#include "architecture/heliotropism.hpp"
#include "geometry/angles.hpp"
#include "geometry/vector_checks.hpp"

namespace heliostand {
namespace {

using testing::angle_between;

TEST(Heliotropism, HorizontalBranchUnderZenithLightRisesByIOfTheRightAngle) {
  // 90° between branch and light; I = 0.4 turns it 36° up, in the vertical xz plane.
  const glm::dvec3 turned = heliotropic_direction({2.0, 0.0, 0.0}, {0.0, 0.0, 5.0}, 0.4);
  EXPECT_NEAR(turned.x, std::cos(radians(36.0)), 1e-12);
  EXPECT_NEAR(turned.y, 0.0, 1e-12);
  EXPECT_NEAR(turned.z, std::sin(radians(36.0)), 1e-12);
  EXPECT_NEAR(glm::length(turned), 1.0, 1e-12);
}

TEST(Heliotropism, TurnsInThePlaneOfBranchAndLightVectorTowardTheLight) {
  const glm::dvec3 branch{1.0, 1.0, 0.2}, light{-0.3, 1.0, 0.8};
  const double before = angle_between(branch, light);
  for (double strength : {0.1, 0.4, 0.8}) {
    const glm::dvec3 turned = heliotropic_direction(branch, light, strength);
    EXPECT_NEAR(angle_between(turned, light), (1.0 - strength) * before, 1e-9) << strength;
    EXPECT_NEAR(angle_between(turned, branch), strength * before, 1e-9) << strength;
    // Coplanar with the branch and the light vector.
    EXPECT_NEAR(glm::dot(turned, glm::cross(branch, light)), 0.0, 1e-12) << strength;
  }
}

TEST(Heliotropism, NoStrengthOrNoLightVectorLeavesTheBranch) {
  const glm::dvec3 branch = glm::normalize(glm::dvec3{0.3, -0.2, 0.9});
  const glm::dvec3 none = heliotropic_direction(branch, {0.0, 0.0, 0.0}, 0.4);
  const glm::dvec3 weak = heliotropic_direction(branch, {1.0, 0.0, 0.0}, 0.0);
  EXPECT_NEAR(glm::length(none - branch), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(weak - branch), 0.0, 1e-12);
}

TEST(Heliotropism, FullStrengthPointsAlongTheLight) {
  const glm::dvec3 turned = heliotropic_direction({0.0, 1.0, -0.5}, {1.0, 0.0, 1.0}, 1.0);
  EXPECT_NEAR(angle_between(turned, {1.0, 0.0, 1.0}), 0.0, 1e-9);
}

TEST(Heliotropism, BranchPointingAwayFromTheLightTurnsThroughTheVertical) {
  // Straight down under zenith light: the plane is undefined; it turns by I * 180°.
  const glm::dvec3 turned = heliotropic_direction({0.0, 0.0, -1.0}, {0.0, 0.0, 1.0}, 0.5);
  EXPECT_NEAR(turned.z, 0.0, 1e-12);
  EXPECT_NEAR(glm::length(turned), 1.0, 1e-12);
}

TEST(DeathThreshold, DrawsWithinD0PlusMinusTheDitherAndCoversTheRange) {
  const DeathThreshold threshold{0.6, 0.3};
  RandomStream random(11, {3});
  double low = 1e9, high = -1e9, sum = 0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const double d = threshold.draw(random);
    ASSERT_GE(d, 0.3);
    ASSERT_LT(d, 0.9);
    low = std::min(low, d);
    high = std::max(high, d);
    sum += d;
  }
  EXPECT_LT(low, 0.31);
  EXPECT_GT(high, 0.89);
  EXPECT_NEAR(sum / n, 0.6, 0.01);
}

TEST(DeathThreshold, BranchDiesOnlyBelowItsThreshold) {
  EXPECT_TRUE(dies_of_shade(0.59, 0.6));
  EXPECT_FALSE(dies_of_shade(0.6, 0.6));
  EXPECT_FALSE(dies_of_shade(0.9, 0.6));
}

}  // namespace
}  // namespace heliostand
