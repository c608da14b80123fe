#include "geometry/convex_hull.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>

#include <glm/geometric.hpp>

#include <libqhull_r/qhull_ra.h>

namespace heliostand {
namespace {

// Qhull writes its errors to a C stream; this one collects them in memory for the exception's message (stderr
// should the stream not open).
class MessageStream {
 public:
  MessageStream() : file_(open_memstream(&text_, &size_)) {}
  ~MessageStream() {
    if (file_) std::fclose(file_);
    std::free(text_);
  }
  MessageStream(const MessageStream&) = delete;
  MessageStream& operator=(const MessageStream&) = delete;

  std::FILE* file() const { return file_ ? file_ : stderr; }
  std::string text() {
    if (file_) std::fflush(file_);
    return text_ ? std::string(text_, size_) : std::string();
  }

 private:
  char* text_ = nullptr;
  std::size_t size_ = 0;
  std::FILE* file_;
};

// One run of Qhull: its state, freed however the run ends.
class QhullRun {
 public:
  explicit QhullRun(std::FILE* errors) { qh_zero(&qh_, errors); }
  ~QhullRun() {
    qh_freeqhull(&qh_, !qh_ALL);
    int still_long = 0, total_long = 0;
    qh_memfreeshort(&qh_, &still_long, &total_long);
  }
  QhullRun(const QhullRun&) = delete;
  QhullRun& operator=(const QhullRun&) = delete;

  qhT* qh() { return &qh_; }

 private:
  qhT qh_;
};

glm::dvec3 vec3(const coordT* p) { return {p[0], p[1], p[2]}; }

}  // namespace

ConvexHull convex_hull(std::span<const glm::dvec3> points) {
  if (points.size() < 4) throw FlatPointSet("fewer than four points span no volume");
  std::vector<coordT> coordinates;
  coordinates.reserve(3 * points.size());
  for (const glm::dvec3& p : points) coordinates.insert(coordinates.end(), {p.x, p.y, p.z});

  MessageStream errors;
  QhullRun run(errors.file());
  qhT* qh = run.qh();
  // Qt: faces of more than three corners (merged where points are coplanar within rounding) come out as triangles.
  char options[] = "qhull Qt";
  if (qh_new_qhull(qh, 3, static_cast<int>(points.size()), coordinates.data(), False, options, nullptr,
                   errors.file()) != 0)
    throw FlatPointSet("Qhull found no hull: " + errors.text());

  // The corners in input order, renumbered from 0.
  std::vector<int> corner_of(points.size(), -1);
  vertexT* vertex;
  FORALLvertices corner_of[static_cast<std::size_t>(qh_pointid(qh, vertex->point))] = 0;
  ConvexHull hull;
  for (std::size_t p = 0; p < points.size(); ++p)
    if (corner_of[p] == 0) {
      corner_of[p] = static_cast<int>(hull.corners.size());
      hull.corners.push_back(points[p]);
    }

  facetT* facet;
  FORALLfacets {
    if (qh_setsize(qh, facet->vertices) != 3) throw std::logic_error("Qhull left a face of the hull untriangulated");
    std::array<int, 3> triangle{};
    int k = 0;
    vertexT** vertexp;
    FOREACHvertex_(facet->vertices) triangle[k++] = corner_of[static_cast<std::size_t>(qh_pointid(qh, vertex->point))];
    // Qhull lists a facet's vertices by id, not around it: turn it so its normal agrees with the facet's outward one.
    const glm::dvec3 a = hull.corners[triangle[0]], b = hull.corners[triangle[1]], c = hull.corners[triangle[2]];
    if (glm::dot(glm::cross(b - a, c - a), vec3(facet->normal)) < 0) std::swap(triangle[1], triangle[2]);
    // Its smallest corner first, and the triangles sorted below: one order whatever Qhull's facet list.
    std::rotate(triangle.begin(), std::min_element(triangle.begin(), triangle.end()), triangle.end());
    hull.triangles.push_back(triangle);
  }
  std::sort(hull.triangles.begin(), hull.triangles.end());
  return hull;
}

}  // namespace heliostand
