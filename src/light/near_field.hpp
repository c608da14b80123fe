#pragma once
// Candidate culling: a k-d tree (FLANN KDTreeSingleIndex, deterministic) over occluder centres, rebuilt
// every solve. Receivers are grouped into cubic tiles and one radius search per tile, from the tile's centre
// out to the cut-off plus the tile's half-diagonal, finds every occluder that can lie within the cut-off of
// any receiver in it; each receiver then keeps those within the cut-off of its own centre. A tile's
// receivers share one list (a few dozen balls read one list instead of each writing ~600 indices of its own),
// which is what makes the search and its memory small for a stand of a million balls. The list is kept in
// shells of distance from the tile's centre, nearest first, so that a receiver near the centre stops early:
// an occluder within the cut-off of a receiver at distance e from the centre lies within cut-off + e of it.
// The result is CSR arrays, the layout the OpenCL kernel reads.
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "light/occluders.hpp"

namespace heliostand {

struct TileCandidates {
  // Receiver slots (positions in the receiver list) ordered by tile: tile t holds
  // slots[slot_start[t] .. slot_start[t+1]).
  std::vector<std::uint32_t> slots;
  std::vector<std::uint32_t> slot_start;
  // Occluders (indices into the OccluderSet) whose centre lies within cut-off + half-diagonal of tile t's
  // centre: occluders[start[t] .. start[t+1]). A receiver itself is among its tile's occluders: skip it.
  // `occluders` stays empty where the lists were laid out in a place of the caller's (TileListPlace).
  std::vector<std::uint32_t> start;
  std::vector<std::uint32_t> occluders;
  // Per receiver slot position k (as `slots`): the end of the part of its tile's list that can hold an
  // occluder within the cut-off of that receiver, start[t] <= scan_end[k] <= start[t+1]. The list is laid
  // out in near_field_shells shells of distance from the tile's centre; a receiver scans the shells up to
  // cut-off + its own distance from the centre (+ 1 mm, far above the round-off of the kernel's float test).
  std::vector<std::uint32_t> scan_end;
  std::size_t tile_count() const { return slot_start.empty() ? 0 : slot_start.size() - 1; }
  std::size_t entry_count() const { return start.empty() ? 0 : start.back(); }  // of every tile's list together
};

// Where the tiles' occluder lists go, end to end, instead of TileCandidates::occluders: given how many entries they
// hold, room for that many. The OpenCL solver gives the device buffer its tile scan reads them from, mapped and kept
// from one solve to the next, so that the lists are neither copied nor written to fresh pages each solve (at 10^6
// balls 144 MB twice; docs/performance.md "The tile lists written where the device reads them").
using TileListPlace = std::function<std::span<std::uint32_t>(std::size_t entries)>;

// Tile edge for a cut-off: three quarters of the cut-off balances fewer searches (bigger tiles) against more occluders to
// discard by distance in each receiver's loop (measured in docs/performance.md).
inline double tile_edge_for(double cutoff_m) { return 0.75 * cutoff_m; }

// Shells of each tile's list between the cut-off and the search's reach. On a uniform canopy with 2.25 m tiles,
// eight let a receiver scan 0.62 of its tile's list on average (0.57 with no limit; docs/performance.md).
inline constexpr int near_field_shells = 8;

class NearFieldSearch {
 public:
  NearFieldSearch(const OccluderSet& occluders, double cutoff_m);
  ~NearFieldSearch();
  NearFieldSearch(const NearFieldSearch&) = delete;
  NearFieldSearch& operator=(const NearFieldSearch&) = delete;

  // Near-field candidates of the receivers (indices of the stand's balls, i.e. the first ball_count entries of
  // the OccluderSet), grouped into tiles of edge `tile_m`.
  TileCandidates tile_candidates(std::span<const std::uint32_t> receivers, double tile_m) const;
  // The same lists, the occluders' laid out in `place` (called once, after the search; not at all when there are no
  // tiles or no occluders), the result's `occluders` left empty.
  TileCandidates tile_candidates(std::span<const std::uint32_t> receivers, double tile_m,
                                 const TileListPlace& place) const;

  // True when occluder `j` shades receiver ball `i` in the near field: another entry whose centre lies within
  // the cut-off (double precision; the OpenCL kernel makes the same test in float).
  bool within_cutoff(std::uint32_t i, std::uint32_t j) const;

 private:
  struct Index;
  // Both tile_candidates: the lists in `*place`, or in the result's `occluders` where `place` is null.
  TileCandidates lay_out_tiles(std::span<const std::uint32_t> receivers, double tile_m, const TileListPlace* place) const;
  const OccluderSet& occluders_;
  double cutoff_m_;
  std::vector<double> coordinates_;  // row-major n x 3, owned here because FLANN keeps a pointer
  std::unique_ptr<Index> index_;
};

}  // namespace heliostand
