#include "geometry/neighbourhood.hpp"

#include <flann/flann.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace heliostand {

struct Neighbourhood::Index {
  flann::KDTreeSingleIndex<flann::L2_Simple<double>> tree;
  explicit Index(const flann::Matrix<double>& points) : tree(points, flann::KDTreeSingleIndexParams(8)) {}
};

namespace {

// Where a stem's copies stand relative to it: itself only with buffered edges; with periodic edges the 3 x 3
// tiles around the plot, enough for any neighbour closer than one plot width or depth.
std::vector<glm::dvec2> tile_offsets(const StandEdges& edges) {
  if (!edges.periodic) return {{0.0, 0.0}};
  std::vector<glm::dvec2> offsets;
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j) offsets.push_back({i * edges.domain.width_m(), j * edges.domain.depth_m()});
  return offsets;
}

// One coordinate's separation under periodic edges: to the nearest copy, |result| <= period / 2.
double wrapped(double separation, double period) { return separation - period * std::round(separation / period); }

}  // namespace

Neighbourhood::Neighbourhood(std::span<const glm::dvec2> positions, StandEdges edges)
    : positions_(positions.begin(), positions.end()), edges_(edges) {
  for (const glm::dvec2 offset : tile_offsets(edges_))
    for (std::size_t stem = 0; stem < positions_.size(); ++stem) {
      coordinates_.insert(coordinates_.end(), {positions_[stem].x + offset.x, positions_[stem].y + offset.y});
      stem_of_point_.push_back(stem);
    }
  if (positions_.empty()) return;
  index_ = std::make_unique<Index>(flann::Matrix<double>(coordinates_.data(), stem_of_point_.size(), 2));
  index_->tree.buildIndex();
}

Neighbourhood::~Neighbourhood() = default;

std::vector<Neighbour> Neighbourhood::within(std::size_t stem, double radius_m) const {
  std::vector<Neighbour> neighbours;
  if (!index_ || !(radius_m > 0)) return neighbours;
  double query[2] = {positions_[stem].x, positions_[stem].y};
  flann::SearchParams search;
  search.sorted = false;
  search.max_neighbors = -1;
  std::vector<std::vector<std::size_t>> found;
  std::vector<std::vector<double>> squared_distances;
  // FLANN takes the squared radius as a float: search a hair wider, then keep the exact test in double.
  const double reach = radius_m * (1.0 + 1e-6) + 1e-9;
  index_->tree.radiusSearch(flann::Matrix<double>(query, 1, 2), found, squared_distances,
                            static_cast<float>(reach * reach), search);
  for (std::size_t k = 0; k < found[0].size(); ++k) {
    const std::size_t other = stem_of_point_[found[0][k]];
    const double distance = std::sqrt(squared_distances[0][k]);
    if (other != stem && distance < radius_m) neighbours.push_back({other, distance});
  }
  // A radius over half the plot can reach two copies of one stem: it counts once, at its nearest copy.
  std::sort(neighbours.begin(), neighbours.end(), [](const Neighbour& a, const Neighbour& b) {
    return a.stem != b.stem ? a.stem < b.stem : a.distance_m < b.distance_m;
  });
  neighbours.erase(std::unique(neighbours.begin(), neighbours.end(),
                               [](const Neighbour& a, const Neighbour& b) { return a.stem == b.stem; }),
                   neighbours.end());
  return neighbours;
}

std::optional<Neighbour> Neighbourhood::nearest(std::size_t stem) const {
  if (!index_ || positions_.size() < 2) return std::nullopt;
  // Among the 10 closest points at least one is another stem: a stem has at most 9 copies of itself.
  const std::size_t wanted = std::min<std::size_t>(10, stem_of_point_.size());
  double query[2] = {positions_[stem].x, positions_[stem].y};
  std::vector<std::vector<std::size_t>> found;
  std::vector<std::vector<double>> squared_distances;
  index_->tree.knnSearch(flann::Matrix<double>(query, 1, 2), found, squared_distances, wanted, flann::SearchParams());
  std::optional<Neighbour> closest;
  for (std::size_t k = 0; k < found[0].size(); ++k) {
    const std::size_t other = stem_of_point_[found[0][k]];
    const double distance = std::sqrt(squared_distances[0][k]);
    if (other != stem && (!closest || distance < closest->distance_m ||
                          (distance == closest->distance_m && other < closest->stem)))
      closest = Neighbour{other, distance};
  }
  return closest;
}

double Neighbourhood::distance(std::size_t a, std::size_t b) const {
  glm::dvec2 separation = positions_[b] - positions_[a];
  if (edges_.periodic) {
    separation.x = wrapped(separation.x, edges_.domain.width_m());
    separation.y = wrapped(separation.y, edges_.domain.depth_m());
  }
  return std::hypot(separation.x, separation.y);
}

}  // namespace heliostand
