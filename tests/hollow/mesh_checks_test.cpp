// The mesh checks themselves: Möller's triangle test, manifold edges, the grid-culled intersection search.
#include <gtest/gtest.h>

#include "hollow/mesh_checks.hpp"

namespace heliostand::hollow {
namespace {

using V = glm::dvec3;

TEST(TriangleIntersection, CrossingTrianglesIntersect) {
  EXPECT_TRUE(triangles_intersect(V(0, 0, 0), V(1, 0, 0), V(0, 1, 0), V(0.2, 0.2, -1), V(0.2, 0.2, 1), V(1, 1, 0.5)));
}

TEST(TriangleIntersection, SeparatedAndParallelTrianglesDoNot) {
  EXPECT_FALSE(triangles_intersect(V(0, 0, 0), V(1, 0, 0), V(0, 1, 0), V(0, 0, 1), V(1, 0, 1), V(0, 1, 1)));
  // The second one pierces the first one's plane, but outside the first triangle.
  EXPECT_FALSE(triangles_intersect(V(0, 0, 0), V(1, 0, 0), V(0, 1, 0), V(2, 2, -1), V(2, 2, 1), V(3, 3, 0)));
}

TEST(TriangleIntersection, CoplanarOverlapIsFoundAndCoplanarDisjointIsNot) {
  EXPECT_TRUE(triangles_intersect(V(0, 0, 0), V(2, 0, 0), V(0, 2, 0), V(0.5, 0.5, 0), V(3, 0.5, 0), V(0.5, 3, 0)));
  EXPECT_FALSE(triangles_intersect(V(0, 0, 0), V(1, 0, 0), V(0, 1, 0), V(2, 2, 0), V(3, 2, 0), V(2, 3, 0)));
}

TEST(TriangleIntersection, TouchingAtAPointCounts) {
  EXPECT_TRUE(triangles_intersect(V(0, 0, 0), V(1, 0, 0), V(0, 1, 0), V(1, 0, 0), V(2, 0, 1), V(2, 0, -1)));
}

// A closed tetrahedron, outward-oriented.
std::vector<V> tet_vertices() { return {V(0, 0, 0), V(1, 0, 0), V(0, 1, 0), V(0, 0, 1)}; }
std::vector<std::array<int, 3>> tet_faces() { return {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}; }

TEST(ManifoldCheck, ClosedTetrahedronIsManifoldAndConsistent) {
  const ManifoldReport r = check_manifold(tet_vertices(), tet_faces());
  EXPECT_EQ(r.edges, 6);
  EXPECT_EQ(r.boundary_edges, 0);
  EXPECT_TRUE(r.ok());
}

TEST(ManifoldCheck, FlippedFaceAndFinEdgeAreReported) {
  auto faces = tet_faces();
  faces[1] = {0, 3, 1};  // flipped
  EXPECT_GT(check_manifold(tet_vertices(), faces).inconsistent_edges, 0);
  auto vertices = tet_vertices();
  vertices.push_back(V(1, 1, 1));
  faces = tet_faces();
  faces.push_back({1, 2, 4});  // a third face on edge 1–2
  EXPECT_EQ(check_manifold(vertices, faces).non_manifold_edges, 1);
  faces = tet_faces();
  faces.push_back({1, 1, 2});
  EXPECT_EQ(check_manifold(vertices, faces).degenerate_triangles, 1);
}

TEST(SelfIntersection, ClosedSurfaceHasNoneAndAPiercingTriangleIsFound) {
  EXPECT_EQ(find_self_intersections(tet_vertices(), tet_faces()).count, 0);
  auto vertices = tet_vertices();
  vertices.push_back(V(0.2, 0.2, -0.5));
  vertices.push_back(V(0.25, 0.2, 0.5));
  vertices.push_back(V(0.2, 0.25, 0.5));
  auto faces = tet_faces();
  faces.push_back({4, 5, 6});  // pierces the bottom face (z = 0) only
  const IntersectionReport r = find_self_intersections(vertices, faces);
  EXPECT_EQ(r.count, 1);
  ASSERT_EQ(r.intersecting.size(), 1u);
  EXPECT_EQ(r.intersecting[0][0], 0);
  EXPECT_EQ(r.intersecting[0][1], 4);
}

}  // namespace
}  // namespace heliostand::hollow
