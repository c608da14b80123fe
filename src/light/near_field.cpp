#include "light/near_field.hpp"

#include <flann/flann.hpp>

namespace heliostand {

struct NearFieldSearch::Index {
  flann::KDTreeSingleIndex<flann::L2_Simple<double>> tree;
  explicit Index(const flann::Matrix<double>& points) : tree(points, flann::KDTreeSingleIndexParams(16)) {}
};

NearFieldSearch::NearFieldSearch(const OccluderSet& occluders, double cutoff_m)
    : occluders_(occluders), cutoff_m_(cutoff_m) {
  coordinates_.reserve(occluders.centres.size() * 3);
  for (const auto& c : occluders.centres) coordinates_.insert(coordinates_.end(), {c.x, c.y, c.z});
  if (occluders.centres.empty()) return;
  index_ = std::make_unique<Index>(flann::Matrix<double>(coordinates_.data(), occluders.centres.size(), 3));
  index_->tree.buildIndex();
}

NearFieldSearch::~NearFieldSearch() = default;

CandidateLists NearFieldSearch::candidates(std::span<const std::uint32_t> receivers) const {
  CandidateLists lists;
  lists.start.reserve(receivers.size() + 1);
  lists.start.push_back(0);
  if (!index_) {
    lists.start.resize(receivers.size() + 1, 0);
    return lists;
  }
  std::vector<double> queries;
  queries.reserve(receivers.size() * 3);
  for (auto r : receivers) {
    const auto& c = occluders_.centres[r];
    queries.insert(queries.end(), {c.x, c.y, c.z});
  }
  flann::SearchParams search;
  search.sorted = false;   // order does not matter: transmittance is a product
  search.max_neighbors = -1;
  std::vector<std::vector<std::size_t>> found;
  std::vector<std::vector<double>> squared_distances;
  // L2_Simple works on squared distances, so the radius is squared too.
  index_->tree.radiusSearch(flann::Matrix<double>(queries.data(), receivers.size(), 3), found, squared_distances,
                            static_cast<float>(cutoff_m_ * cutoff_m_), search);
  for (std::size_t slot = 0; slot < receivers.size(); ++slot) {
    for (auto k : found[slot])
      if (k != receivers[slot]) lists.occluders.push_back(static_cast<std::uint32_t>(k));
    lists.start.push_back(static_cast<std::uint32_t>(lists.occluders.size()));
  }
  return lists;
}

}  // namespace heliostand
