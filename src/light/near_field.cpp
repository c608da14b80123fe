#include "light/near_field.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <tuple>

#include <flann/flann.hpp>
#include <glm/geometric.hpp>

#include "core/parallel_for.hpp"

namespace heliostand {
namespace {

using TileKey = std::tuple<std::int64_t, std::int64_t, std::int64_t>;

// Tiles a worker thread searches and lays out at a time: some hundreds of occluders each, so blocks stay well above
// the cost of handing them out.
constexpr std::size_t tiles_per_block = 64;

TileKey tile_of(const glm::dvec3& point, double tile_m) {
  return {static_cast<std::int64_t>(std::floor(point.x / tile_m)), static_cast<std::int64_t>(std::floor(point.y / tile_m)),
          static_cast<std::int64_t>(std::floor(point.z / tile_m))};
}

glm::dvec3 tile_centre(const TileKey& key, double tile_m) {
  return (glm::dvec3(std::get<0>(key), std::get<1>(key), std::get<2>(key)) + 0.5) * tile_m;
}

// Shell s of a tile's list holds the occluders at distance (cutoff + s w, cutoff + (s+1) w] from its centre
// (shell 0 also everything nearer, the last everything farther), w = (reach - cutoff) / near_field_shells.
// Compared on squared distances (FLANN's), so that no square root is taken per candidate; the shell of a
// distance never decreases as the distance grows, which is all the scan's bound needs.
class ShellLayout {
 public:
  ShellLayout(double cutoff_m, double reach_m) {
    const double width = (reach_m - cutoff_m) / near_field_shells;
    for (int s = 0; s + 1 < near_field_shells; ++s) outer_squared_[s] = std::pow(cutoff_m + (s + 1) * width, 2);
  }
  // The first shell whose outer bound is at least sqrt(squared_distance).
  std::uint8_t of_squared(double squared_distance) const {
    int shell = 0;
    for (double bound : outer_squared_) shell += squared_distance > bound ? 1 : 0;
    return static_cast<std::uint8_t>(shell);
  }

 private:
  std::array<double, near_field_shells - 1> outer_squared_{};
};

// One tile's occluders within the search's radius, in the order FLANN's walk of the k-d tree finds them (the order
// its batch radius search returned them in, unsorted), each with its shell. The batch search gave each tile two
// vectors of its own, an index and a distance per occluder (577 MB at 10^6 balls); a collector per block of tiles is
// reused instead, and the tiles' searches run on the worker threads rather than through FLANN's OpenMP loop.
class ShellCollector : public flann::ResultSet<double> {
 public:
  ShellCollector(double radius_squared, const ShellLayout& shells) : radius_squared_(radius_squared), shells_(shells) {}
  void clear() { found.clear(), shell.clear(); }
  bool full() const override { return true; }
  void addPoint(double squared_distance, std::size_t index) override {
    if (!(squared_distance < radius_squared_)) return;
    found.push_back(static_cast<std::uint32_t>(index));
    shell.push_back(shells_.of_squared(squared_distance));
  }
  double worstDist() const override { return radius_squared_; }

  std::vector<std::uint32_t> found;
  std::vector<std::uint8_t> shell;

 private:
  double radius_squared_;
  const ShellLayout& shells_;
};

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

namespace {

// Groups the receiver slots by tile into `lists` (slots, slot_start), sorted by (tile, slot) so that the order is
// reproducible, and returns each tile's centre, x y z one tile after another.
std::vector<double> group_by_tile(std::span<const std::uint32_t> receivers, const OccluderSet& occluders, double tile_m,
                                  TileCandidates& lists) {
  std::vector<std::pair<TileKey, std::uint32_t>> keyed(receivers.size());
  for (std::uint32_t slot = 0; slot < receivers.size(); ++slot)
    keyed[slot] = {tile_of(occluders.centres[receivers[slot]], tile_m), slot};
  std::sort(keyed.begin(), keyed.end());
  lists.slots.reserve(receivers.size());
  lists.slot_start.push_back(0);
  std::vector<double> centres;
  for (std::size_t k = 0; k < keyed.size(); ++k) {
    lists.slots.push_back(keyed[k].second);
    if (k + 1 < keyed.size() && keyed[k + 1].first == keyed[k].first) continue;
    lists.slot_start.push_back(static_cast<std::uint32_t>(lists.slots.size()));
    const glm::dvec3 centre = tile_centre(keyed[k].first, tile_m);
    centres.insert(centres.end(), {centre.x, centre.y, centre.z});
  }
  return centres;
}

// Each tile's list where the block of tiles that found it left it (`block_lists`, `tile_size` entries a tile) put
// in its place in `place`'s room, or in `lists.occluders` without one, and each receiver's scan end made absolute. The
// lists are indexed with 32 bits.
void place_tile_lists(std::vector<std::vector<std::uint32_t>>& block_lists, std::span<const std::uint32_t> tile_size,
                      const TileListPlace* place, TileCandidates& lists) {
  const std::size_t tile_count = tile_size.size();
  lists.start.resize(tile_count + 1);
  std::uint64_t total = 0;
  for (std::size_t t = 0; t < tile_count; ++t) {
    total += tile_size[t];
    if (total > std::numeric_limits<std::uint32_t>::max())
      throw std::runtime_error("the light's near-field tile lists hold more than 2^32 entries; use a shorter [light] "
                               "cutoff_m or a smaller stand");
    lists.start[t + 1] = std::uint32_t(total);
  }
  std::span<std::uint32_t> room;
  if (place != nullptr) {
    room = (*place)(total);
    if (room.size() < total) throw std::logic_error("a place for the light's tile lists gave less room than asked");
  } else {
    lists.occluders.resize(total);
    room = lists.occluders;
  }
  parallel_for_blocks(tile_count, tiles_per_block, [&](std::size_t first_tile, std::size_t last_tile) {
    std::vector<std::uint32_t>& out = block_lists[first_tile / tiles_per_block];
    std::copy(out.begin(), out.end(), room.begin() + lists.start[first_tile]);
    std::vector<std::uint32_t>().swap(out);
    for (std::size_t t = first_tile; t < last_tile; ++t)
      for (auto k = lists.slot_start[t]; k < lists.slot_start[t + 1]; ++k) lists.scan_end[k] += lists.start[t];
  });
}

}  // namespace

TileCandidates NearFieldSearch::tile_candidates(std::span<const std::uint32_t> receivers, double tile_m) const {
  return lay_out_tiles(receivers, tile_m, nullptr);
}

TileCandidates NearFieldSearch::tile_candidates(std::span<const std::uint32_t> receivers, double tile_m,
                                                const TileListPlace& place) const {
  return lay_out_tiles(receivers, tile_m, &place);
}

TileCandidates NearFieldSearch::lay_out_tiles(std::span<const std::uint32_t> receivers, double tile_m,
                                              const TileListPlace* place) const {
  TileCandidates lists;
  lists.start.push_back(0);
  const std::vector<double> queries = group_by_tile(receivers, occluders_, tile_m, lists);
  const std::size_t tile_count = lists.tile_count();
  if (!index_ || tile_count == 0) {
    lists.start.resize(tile_count + 1, 0);
    lists.scan_end.assign(lists.slots.size(), 0);
    return lists;
  }
  // Every point of a tile lies within its half-diagonal of the centre; L2_Simple works on squared distances.
  // The 1e-4 relative slack covers the float radius FLANN's batch search took (kept: the same occluders as
  // before): a few extra occluders, discarded by distance.
  const double reach = (cutoff_m_ + 0.5 * std::sqrt(3.0) * tile_m) * (1.0 + 1e-4);
  const double radius_squared = static_cast<float>(reach * reach);
  const ShellLayout shells{cutoff_m_, reach};
  // Each tile's occluders in shells of distance from its centre, in the order FLANN found them within a shell
  // (deterministic: one query's walk of the tree). The order cannot change the light: every near-field hit
  // multiplies a patch by the same transmittance t (adds the same log t on OpenCL), so a patch's value depends
  // only on how many balls hit it. A full sort took half of the search (10^6 balls: 2.06 -> 1.06 s without it,
  // outputs byte-identical; docs/performance.md); shells are one counting pass.
  // Blocks of tiles on the worker threads, each tile's list in its block's own array, then copied to its place.
  std::vector<std::vector<std::uint32_t>> block_lists((tile_count + tiles_per_block - 1) / tiles_per_block);
  std::vector<std::uint32_t> tile_size(tile_count);
  lists.scan_end.resize(lists.slots.size());  // relative to the tile's start until its place is known
  parallel_for_blocks(tile_count, tiles_per_block, [&](std::size_t first_tile, std::size_t last_tile) {
    ShellCollector collector(radius_squared, shells);
    const flann::SearchParams exact;  // eps 0: every occluder within the radius
    std::array<std::uint32_t, near_field_shells> shell_size{}, shell_end{};
    std::vector<std::uint32_t>& out = block_lists[first_tile / tiles_per_block];
    for (std::size_t t = first_tile; t < last_tile; ++t) {
      collector.clear();
      index_->tree.findNeighbors(collector, &queries[3 * t], exact);
      const std::size_t first = out.size();
      shell_size.fill(0);
      for (const std::uint8_t shell : collector.shell) ++shell_size[shell];
      // Each shell's first place; placing its occluders moves it to the shell's end.
      std::exclusive_scan(shell_size.begin(), shell_size.end(), shell_end.begin(), std::uint32_t(first));
      out.resize(first + collector.found.size());
      for (std::size_t k = 0; k < collector.found.size(); ++k) out[shell_end[collector.shell[k]]++] = collector.found[k];
      tile_size[t] = std::uint32_t(collector.found.size());
      const glm::dvec3 centre(queries[3 * t], queries[3 * t + 1], queries[3 * t + 2]);
      for (auto k = lists.slot_start[t]; k < lists.slot_start[t + 1]; ++k) {
        const double need = cutoff_m_ + glm::distance(occluders_.centres[receivers[lists.slots[k]]], centre) + 1e-3;
        lists.scan_end[k] = shell_end[shells.of_squared(need * need)] - std::uint32_t(first);
      }
    }
  });
  place_tile_lists(block_lists, tile_size, place, lists);
  return lists;
}

}  // namespace heliostand
