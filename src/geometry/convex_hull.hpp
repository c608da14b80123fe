#pragma once
// The convex hull of a point set as a closed triangle surface, from Qhull (C. B. Barber, D. P. Dobkin and
// H. Huhdanpaa, "The Quickhull algorithm for convex hulls", ACM Trans. Math. Software 22(4), 1996), whose exact
// predicates and facet merging keep the surface closed where nearly coplanar or cospherical points (a crown's
// symmetric whorls) make a Delaunay tetrahedralisation leave slivers and holes (docs/formats.md, block
// `crown_envelope`).
#include <array>
#include <span>
#include <stdexcept>
#include <vector>

#include <glm/vec3.hpp>

namespace heliostand {

struct ConvexHull {
  // The points that are corners of the hull, in the order they came in (a point inside the hull or on one of its
  // faces is not a corner).
  std::vector<glm::dvec3> corners;
  // Each triangle's three corners (indices into `corners`), counter-clockwise seen from outside, so the right-hand
  // normal points out. Every edge is shared by exactly two triangles; a face of more than three corners is split
  // into triangles.
  std::vector<std::array<int, 3>> triangles;
};

// Thrown when the points span no volume (fewer than four, or all on one plane); the message is Qhull's.
class FlatPointSet : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Safe to call from several threads at once (each call has Qhull state of its own).
ConvexHull convex_hull(std::span<const glm::dvec3> points);

}  // namespace heliostand
