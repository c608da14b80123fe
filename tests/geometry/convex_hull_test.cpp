// geometry/convex_hull.hpp: the hull is closed (every edge on exactly two triangles, run in opposite directions),
// its triangles face outwards, its corners are the extreme points only, and flat input is refused.
#include "geometry/convex_hull.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "hollow/mesh_checks.hpp"
#include "rng/random_stream.hpp"

namespace heliostand {
namespace {

using ::testing::HasSubstr;

// Closed and consistently turned (hollow/mesh_checks.hpp): every edge on exactly two triangles, which run it in
// opposite directions.
void expect_closed_and_consistent(const ConvexHull& hull) {
  const hollow::ManifoldReport edges = hollow::check_manifold(hull.corners, hull.triangles);
  EXPECT_EQ(edges.boundary_edges, 0);
  EXPECT_EQ(edges.non_manifold_edges, 0);
  EXPECT_EQ(edges.inconsistent_edges, 0);
  // Euler's formula for a closed triangulated sphere.
  EXPECT_EQ(hull.triangles.size(), 2 * hull.corners.size() - 4);
}

// Every triangle's right-hand normal points away from the hull's inside (the corners' mean).
void expect_facing_out(const ConvexHull& hull) {
  glm::dvec3 inside(0);
  for (const glm::dvec3& c : hull.corners) inside += c / static_cast<double>(hull.corners.size());
  for (const auto& t : hull.triangles) {
    const glm::dvec3 a = hull.corners[t[0]], b = hull.corners[t[1]], c = hull.corners[t[2]];
    EXPECT_GT(glm::dot(glm::cross(b - a, c - a), a - inside), 0.0);
  }
}

TEST(ConvexHull, ACubeWithPointsInsideAndOnItsFacesHasItsEightCornersOnly) {
  std::vector<glm::dvec3> points = {{0.5, 0.5, 0.5}, {0.5, 0.5, 0}, {0.5, 0, 0.5}};  // inside, on faces
  for (int i = 0; i < 8; ++i) points.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  points.emplace_back(0.25, 0.75, 0.5);
  const ConvexHull hull = convex_hull(points);
  ASSERT_EQ(hull.corners.size(), 8u);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(hull.corners[i], points[3 + i]) << "the corners keep the input's order";
  EXPECT_EQ(hull.triangles.size(), 12u);  // each square face split in two
  expect_closed_and_consistent(hull);
  expect_facing_out(hull);
}

TEST(ConvexHull, RandomCloudsAreClosedAndFaceOutwards) {
  RandomStream random(5);
  for (int cloud = 0; cloud < 20; ++cloud) {
    std::vector<glm::dvec3> points;
    for (int i = 0; i < 200; ++i)
      points.emplace_back(random.uniform(-1, 1), random.uniform(-1, 1), 10 + random.uniform(-3, 3));
    const ConvexHull hull = convex_hull(points);
    ASSERT_GE(hull.corners.size(), 4u);
    expect_closed_and_consistent(hull);
    expect_facing_out(hull);
  }
}

TEST(ConvexHull, FlatOrTooFewPointsAreRefused) {
  EXPECT_THROW(convex_hull(std::vector<glm::dvec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), FlatPointSet);
  try {
    convex_hull(std::vector<glm::dvec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0.5, 0.2, 0}});
    FAIL() << "points on one plane were taken";
  } catch (const FlatPointSet& flat) {
    EXPECT_THAT(flat.what(), HasSubstr("Qhull"));
  }
}

}  // namespace
}  // namespace heliostand
