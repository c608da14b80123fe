#include "roots/root_direction.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "geometry/angles.hpp"
#include "geometry/vector_checks.hpp"

namespace heliostand::roots {
namespace {

constexpr double exact = 1e-12;

using testing::expect_near;

double angle_between_deg(const glm::dvec3& a, const glm::dvec3& b) {
  return degrees(testing::angle_between(a, b));
}

TEST(RootDirection, InheritedDirectionTurnsWithinTheBranchingAngleRange) {
  RandomStream random(7, {1});
  const glm::dvec3 parent = glm::normalize(glm::dvec3(1.0, 2.0, -0.5));
  double smallest = 180.0, largest = 0.0;
  for (int draw = 0; draw < 500; ++draw) {
    const glm::dvec3 turned = rotate_within_range(parent, {60.0, 90.0}, random);
    EXPECT_NEAR(glm::length(turned), 1.0, 1e-12);
    smallest = std::min(smallest, angle_between_deg(parent, turned));
    largest = std::max(largest, angle_between_deg(parent, turned));
  }
  EXPECT_GE(smallest, 60.0 - 1e-9);
  EXPECT_LE(largest, 90.0 + 1e-9);
  EXPECT_LT(smallest, 62.0);  // the whole range is used
  EXPECT_GT(largest, 88.0);
  EXPECT_NEAR(angle_between_deg(parent, rotate_within_range(parent, {30.0, 30.0}, random)), 30.0, 1e-9);
}

TEST(RootDirection, DiagravitropicVectorIsTheDirectionLaidHorizontalInItsVerticalPlane) {
  expect_near(horizontal_of({1.0, 0.0, -1.0}, {0.0, 1.0, 0.0}), {1.0, 0.0, 0.0}, exact);
  expect_near(horizontal_of({3.0, 4.0, 10.0}, {0.0, 1.0, 0.0}), {0.6, 0.8, 0.0}, exact);
  expect_near(horizontal_of({0.0, 0.0, -1.0}, {0.0, 2.0, 0.0}), {0.0, 1.0, 0.0}, exact);  // vertical: the fallback
}

TEST(RootDirection, EachTermAloneGivesItsOwnDirection) {
  TropismVectors vectors;
  vectors.inherited = glm::normalize(glm::dvec3(1.0, 0.0, -1.0));
  vectors.diagravitropic = {1.0, 0.0, 0.0};
  vectors.moisture_pull = {0.0, 3.0, 0.0};
  vectors.contact_avoidance = {-2.0, 0.0, 0.0};
  expect_near(compose_direction({.alpha = 1.0}, vectors), vectors.inherited, exact);
  expect_near(compose_direction({.alpha = 0.0, .beta = 1.0}, vectors), {0.0, 0.0, -1.0}, exact);
  expect_near(compose_direction({.alpha = 0.0, .gamma = 1.0}, vectors), {1.0, 0.0, 0.0}, exact);
  expect_near(compose_direction({.alpha = 0.0, .delta = 1.0}, vectors), {0.0, 1.0, 0.0}, exact);
  expect_near(compose_direction({.alpha = 0.0, .epsilon = 1.0}, vectors), {-1.0, 0.0, 0.0}, exact);
}

TEST(RootDirection, WeightsMixUnitVectors) {
  TropismVectors vectors;
  vectors.inherited = {1.0, 0.0, 0.0};
  // Half inherited (east), half gravity: 45° below the horizontal, whatever the pull's magnitude.
  expect_near(compose_direction({.alpha = 0.5, .beta = 0.5}, vectors),
              glm::normalize(glm::dvec3(1.0, 0.0, -1.0)), exact);
  vectors.moisture_pull = {0.0, 100.0, 0.0};
  expect_near(compose_direction({.alpha = 0.5, .delta = 0.5}, vectors),
              glm::normalize(glm::dvec3(1.0, 1.0, 0.0)), exact);
}

TEST(RootDirection, AnEmptyOrBalancedFieldPullsNowhere) {
  TropismVectors vectors;
  vectors.inherited = {0.0, 1.0, 0.0};
  vectors.moisture_pull = {1e-7, 0.0, 0.0};  // float round-off of a balanced field
  expect_near(compose_direction({.alpha = 0.4, .delta = 0.6}, vectors), {0.0, 1.0, 0.0}, exact);
  expect_near(unit_or_zero({0.0, 0.0, 0.0}), {0.0, 0.0, 0.0}, exact);
  // Opposite terms that cancel exactly keep the inherited direction.
  vectors.inherited = {0.0, 0.0, 1.0};
  expect_near(compose_direction({.alpha = 0.5, .beta = 0.5}, vectors), {0.0, 0.0, 1.0}, exact);
}

TEST(RootDirection, SettingOneWeightRescalesTheOthersToSumOne) {
  const TropismWeights weights = with_weight({.alpha = 0.5, .beta = 0.2, .gamma = 0.3}, Tropism::delta, 0.6);
  EXPECT_DOUBLE_EQ(weights.delta, 0.6);
  EXPECT_DOUBLE_EQ(weights.alpha, 0.2);
  EXPECT_DOUBLE_EQ(weights.beta, 0.08);
  EXPECT_NEAR(weights.gamma, 0.12, 1e-15);
  EXPECT_NEAR(weights.sum(), 1.0, 1e-15);
}

}  // namespace
}  // namespace heliostand::roots
