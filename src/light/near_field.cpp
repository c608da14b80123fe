#include "light/near_field.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include <flann/flann.hpp>
#include <glm/geometric.hpp>

namespace heliostand {
namespace {

using TileKey = std::tuple<std::int64_t, std::int64_t, std::int64_t>;

TileKey tile_of(const glm::dvec3& point, double tile_m) {
  return {static_cast<std::int64_t>(std::floor(point.x / tile_m)), static_cast<std::int64_t>(std::floor(point.y / tile_m)),
          static_cast<std::int64_t>(std::floor(point.z / tile_m))};
}

glm::dvec3 tile_centre(const TileKey& key, double tile_m) {
  return (glm::dvec3(std::get<0>(key), std::get<1>(key), std::get<2>(key)) + 0.5) * tile_m;
}

}  // namespace

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

bool NearFieldSearch::within_cutoff(std::uint32_t i, std::uint32_t j) const {
  if (i == j) return false;
  const glm::dvec3 d = occluders_.centres[j] - occluders_.centres[i];
  return glm::dot(d, d) <= cutoff_m_ * cutoff_m_;
}

TileCandidates NearFieldSearch::tile_candidates(std::span<const std::uint32_t> receivers, double tile_m) const {
  // Group the receiver slots by tile: sorted by (tile, slot), so the order is reproducible.
  std::vector<std::pair<TileKey, std::uint32_t>> keyed(receivers.size());
  for (std::uint32_t slot = 0; slot < receivers.size(); ++slot)
    keyed[slot] = {tile_of(occluders_.centres[receivers[slot]], tile_m), slot};
  std::sort(keyed.begin(), keyed.end());

  TileCandidates lists;
  lists.slots.reserve(receivers.size());
  lists.slot_start.push_back(0);
  lists.start.push_back(0);
  std::vector<double> queries;
  for (std::size_t k = 0; k < keyed.size(); ++k) {
    lists.slots.push_back(keyed[k].second);
    if (k + 1 < keyed.size() && keyed[k + 1].first == keyed[k].first) continue;
    lists.slot_start.push_back(static_cast<std::uint32_t>(lists.slots.size()));
    const glm::dvec3 centre = tile_centre(keyed[k].first, tile_m);
    queries.insert(queries.end(), {centre.x, centre.y, centre.z});
  }
  const std::size_t tile_count = lists.tile_count();
  if (!index_ || tile_count == 0) {
    lists.start.resize(tile_count + 1, 0);
    return lists;
  }
  flann::SearchParams search;
  search.sorted = false;   // order does not matter: transmittance is a product
  search.max_neighbors = -1;
  search.cores = 0;        // all cores (FLANN's OpenMP loop over the queries)
  std::vector<std::vector<std::size_t>> found;
  std::vector<std::vector<double>> squared_distances;
  // Every point of a tile lies within its half-diagonal of the centre; L2_Simple works on squared distances.
  // The 1e-4 relative slack covers FLANN's float radius: a few extra occluders, discarded by distance.
  const double reach = (cutoff_m_ + 0.5 * std::sqrt(3.0) * tile_m) * (1.0 + 1e-4);
  index_->tree.radiusSearch(flann::Matrix<double>(queries.data(), tile_count, 3), found, squared_distances,
                            static_cast<float>(reach * reach), search);
  // Each tile's occluders in the order FLANN found them (deterministic: one query's walk of the tree). The order
  // cannot change the light: every near-field hit multiplies a patch by the same transmittance t (adds the same
  // log t on OpenCL), so a patch's value depends only on how many balls hit it. Sorting the lists took half of
  // the search (10^6 balls: 2.06 -> 1.06 s, outputs byte-identical; docs/performance.md).
  std::size_t total = 0;
  for (const auto& tile : found) total += tile.size();
  lists.occluders.reserve(total);
  lists.start.reserve(tile_count + 1);
  for (const auto& tile : found) {
    for (auto k : tile) lists.occluders.push_back(static_cast<std::uint32_t>(k));
    lists.start.push_back(static_cast<std::uint32_t>(lists.occluders.size()));
  }
  return lists;
}

}  // namespace heliostand
