// The tiled near-field search: every receiver lands in exactly one tile, and the part of its tile's list it
// scans (up to its scan_end) holds every occluder within the cut-off of the receiver (checked against a
// brute-force scan), so the per-receiver distance test in both solvers sees the same set the per-ball search of
// earlier versions found.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <span>
#include <stdexcept>
#include <vector>

#include <glm/geometric.hpp>

#include "core/parallel_for.hpp"
#include "light/near_field.hpp"
#include "light/occluders.hpp"
#include "rng/random_stream.hpp"

namespace heliostand {
namespace {

std::vector<LeafBall> scattered_balls(std::size_t count, double size, std::uint64_t seed) {
  RandomStream random(seed, {11});
  std::vector<LeafBall> balls;
  for (std::size_t k = 0; k < count; ++k)
    balls.push_back({{random.uniform(0, size), random.uniform(0, size), random.uniform(0, 0.5 * size)}, 0.2});
  return balls;
}

void expect_tiles_hold_every_near_occluder(const OccluderSet& set, std::span<const std::uint32_t> receivers,
                                           double cutoff, double tile) {
  const NearFieldSearch search(set, cutoff);
  const TileCandidates near = search.tile_candidates(receivers, tile);
  ASSERT_EQ(near.slot_start.back(), receivers.size());
  std::vector<std::uint32_t> slots = near.slots;
  std::sort(slots.begin(), slots.end());
  std::vector<std::uint32_t> every(receivers.size());
  std::iota(every.begin(), every.end(), 0u);
  EXPECT_EQ(slots, every) << "each receiver slot in exactly one tile";
  ASSERT_EQ(near.scan_end.size(), receivers.size());
  std::size_t near_pairs = 0, scanned = 0, listed = 0;
  for (std::size_t t = 0; t < near.tile_count(); ++t) {
    std::vector<std::uint32_t> list(near.occluders.begin() + near.start[t], near.occluders.begin() + near.start[t + 1]);
    std::sort(list.begin(), list.end());
    EXPECT_EQ(std::adjacent_find(list.begin(), list.end()), list.end()) << "tile " << t << " lists an occluder twice";
    for (auto k = near.slot_start[t]; k < near.slot_start[t + 1]; ++k) {
      ASSERT_GE(near.scan_end[k], near.start[t]);
      ASSERT_LE(near.scan_end[k], near.start[t + 1]);
      scanned += near.scan_end[k] - near.start[t];
      listed += near.start[t + 1] - near.start[t];
      // The part this receiver scans, in shell order (the light does not depend on it); sorted to look them up.
      std::vector<std::uint32_t> part(near.occluders.begin() + near.start[t], near.occluders.begin() + near.scan_end[k]);
      std::sort(part.begin(), part.end());
      const std::uint32_t receiver = receivers[near.slots[k]];
      for (std::uint32_t j = 0; j < set.centres.size(); ++j) {
        if (!search.within_cutoff(receiver, j)) continue;
        ++near_pairs;
        EXPECT_TRUE(std::binary_search(part.begin(), part.end(), j))
            << "occluder " << j << " at " << glm::distance(set.centres[j], set.centres[receiver])
            << " m of receiver " << receiver << " is missing from the part of its tile's list it scans ("
            << (std::binary_search(list.begin(), list.end(), j) ? "listed farther on" : "not listed at all") << ")";
      }
    }
  }
  EXPECT_GT(near_pairs, 10 * receivers.size());  // the scene really has a near field
  // The shells are what make the scan short: a receiver stops before the end of its tile's list on average
  // (a uniform scene scans ~0.6 of it with 8 shells when tiles are not much smaller than the cut-off).
  if (tile >= 0.5 * cutoff) EXPECT_LT(double(scanned), 0.8 * double(listed)) << "tile " << tile << " m";
}

TEST(NearFieldSearch, EveryTileListHoldsEveryOccluderWithinTheCutoffOfItsReceivers) {
  const auto balls = scattered_balls(1500, 12.0, 1);
  const OccluderSet set = make_occluder_set(balls, PlotTorus{}, 0.0);
  std::vector<std::uint32_t> receivers(balls.size());
  std::iota(receivers.begin(), receivers.end(), 0u);
  for (double tile : {0.5, 1.5, 3.0}) expect_tiles_hold_every_near_occluder(set, receivers, 2.0, tile);
}

TEST(NearFieldSearch, PeriodicImagesAndASubsetOfReceiversAreFound) {
  const auto balls = scattered_balls(800, 8.0, 2);
  LightParameters p;
  p.periodic = true;
  p.plot_x_max = p.plot_y_max = 8.0;
  const OccluderSet set = make_occluder_set(balls, PlotTorus::from(p), 2.0);
  ASSERT_GT(set.centres.size(), balls.size());  // images across the edges exist
  std::vector<std::uint32_t> receivers;
  for (std::uint32_t k = 0; k < balls.size(); k += 7) receivers.push_back(k);
  expect_tiles_hold_every_near_occluder(set, receivers, 2.0, tile_edge_for(2.0));
}

// The tiles' lists are laid out in blocks of tiles on the worker threads: the same lists, entry for entry, on any
// number of them (the light's order of occluders, and so its float sums on a GPU, depends on them).
TEST(NearFieldSearch, TheSameListsOnAnyNumberOfThreads) {
  const auto balls = scattered_balls(3000, 14.0, 3);
  const OccluderSet set = make_occluder_set(balls, PlotTorus{}, 0.0);
  std::vector<std::uint32_t> receivers(balls.size());
  std::iota(receivers.begin(), receivers.end(), 0u);
  const NearFieldSearch search(set, 2.0);
  set_worker_threads(1);
  const TileCandidates in_order = search.tile_candidates(receivers, tile_edge_for(2.0));
  ASSERT_GT(in_order.tile_count(), 2 * 64u);  // more than one block of tiles
  for (unsigned threads : {2u, 3u, 8u}) {
    set_worker_threads(threads);
    const TileCandidates near = search.tile_candidates(receivers, tile_edge_for(2.0));
    EXPECT_EQ(near.slots, in_order.slots) << threads << " threads";
    EXPECT_EQ(near.slot_start, in_order.slot_start) << threads << " threads";
    EXPECT_EQ(near.start, in_order.start) << threads << " threads";
    EXPECT_EQ(near.occluders, in_order.occluders) << threads << " threads";
    EXPECT_EQ(near.scan_end, in_order.scan_end) << threads << " threads";
  }
  set_worker_threads(0);
}

// The OpenCL solver has the lists written into a device buffer of its own (TileListPlace): the same entries, in the
// same places, as the lists the search keeps itself, and room asked for once, for exactly them; room in a place
// that was not cleared (a buffer a larger solve wrote) is overwritten entry for entry.
TEST(NearFieldSearch, ListsLaidOutInAPlaceOfTheCallersAreTheSame) {
  const auto balls = scattered_balls(2000, 12.0, 4);
  const OccluderSet set = make_occluder_set(balls, PlotTorus{}, 0.0);
  std::vector<std::uint32_t> receivers;
  for (std::uint32_t k = 0; k < balls.size(); k += 3) receivers.push_back(k);
  const NearFieldSearch search(set, 2.0);
  const TileCandidates own = search.tile_candidates(receivers, tile_edge_for(2.0));
  ASSERT_GT(own.tile_count(), 64u);  // more than one block of tiles
  std::vector<std::uint32_t> room(own.occluders.size() + 100, 0xdeadbeefu);  // left as a larger solve left it
  std::vector<std::size_t> asked;
  const TileCandidates placed = search.tile_candidates(receivers, tile_edge_for(2.0), [&](std::size_t entries) {
    asked.push_back(entries);
    return std::span<std::uint32_t>(room.data(), entries);
  });
  EXPECT_EQ(asked, std::vector<std::size_t>{own.occluders.size()});
  EXPECT_TRUE(placed.occluders.empty());
  EXPECT_EQ(placed.entry_count(), own.occluders.size());
  EXPECT_EQ(own.entry_count(), own.occluders.size());
  EXPECT_EQ(std::vector<std::uint32_t>(room.begin(), room.begin() + own.occluders.size()), own.occluders);
  EXPECT_EQ(room[own.occluders.size()], 0xdeadbeefu);  // nothing written beyond the room given
  EXPECT_EQ(placed.slots, own.slots);
  EXPECT_EQ(placed.slot_start, own.slot_start);
  EXPECT_EQ(placed.start, own.start);
  EXPECT_EQ(placed.scan_end, own.scan_end);
}

TEST(NearFieldSearch, APlaceWithTooLittleRoomIsAnError) {
  const auto balls = scattered_balls(300, 6.0, 5);
  const OccluderSet set = make_occluder_set(balls, PlotTorus{}, 0.0);
  std::vector<std::uint32_t> receivers(balls.size());
  std::iota(receivers.begin(), receivers.end(), 0u);
  std::vector<std::uint32_t> room(10);
  const NearFieldSearch search(set, 2.0);
  EXPECT_THROW(search.tile_candidates(receivers, tile_edge_for(2.0),
                                      [&](std::size_t) { return std::span<std::uint32_t>(room); }),
               std::logic_error);
}

TEST(NearFieldSearch, NoOccludersGiveEmptyLists) {
  const OccluderSet set = make_occluder_set({}, PlotTorus{}, 0.0);
  const NearFieldSearch search(set, 4.0);
  const TileCandidates near = search.tile_candidates({}, 3.0);
  EXPECT_EQ(near.tile_count(), 0u);
  EXPECT_TRUE(near.occluders.empty());
}

}  // namespace
}  // namespace heliostand
