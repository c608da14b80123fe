#pragma once
// Checks on directions shared by the tests of branches, roots and the light response.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace heliostand::testing {

// The angle (radians) between two directions of any length.
inline double angle_between(glm::dvec3 a, glm::dvec3 b) {
  return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0));
}

// Each component of `actual` within `tolerance` of `expected`'s.
inline void expect_near(const glm::dvec3& actual, const glm::dvec3& expected, double tolerance) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

}  // namespace heliostand::testing
