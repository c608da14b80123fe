#pragma once
// Checks a hollow mesh must pass: manifold edges, consistent orientation, no self-intersections.
#include <array>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace heliostand::hollow {

struct ManifoldReport {
  int edges = 0;
  int boundary_edges = 0;         // used by one triangle (mesh border, cavity lip, stem base)
  int non_manifold_edges = 0;     // used by more than two triangles
  int inconsistent_edges = 0;     // two triangles traverse the edge in the same direction
  int degenerate_triangles = 0;   // repeated vertex index or (near) zero area
  bool ok() const { return non_manifold_edges == 0 && inconsistent_edges == 0 && degenerate_triangles == 0; }
};

ManifoldReport check_manifold(const std::vector<glm::dvec3>& vertices,
                              const std::vector<std::array<int, 3>>& triangles, double min_area = 1e-14);

// Möller (1997) triangle–triangle test: true when the triangles share a point (touching counts).
bool triangles_intersect(const glm::dvec3& a0, const glm::dvec3& a1, const glm::dvec3& a2,
                         const glm::dvec3& b0, const glm::dvec3& b1, const glm::dvec3& b2);

struct IntersectionReport {
  int pairs_tested = 0;
  std::vector<std::array<int, 2>> intersecting;  // triangle index pairs (at most `limit` listed)
  int count = 0;
};

// All pairs of triangles that share no vertex and intersect, found through a uniform grid of cells about
// the size of a typical triangle (only triangles whose bounding boxes share a cell are tested).
IntersectionReport find_self_intersections(const std::vector<glm::dvec3>& vertices,
                                           const std::vector<std::array<int, 3>>& triangles, int limit = 20);

}  // namespace heliostand::hollow
