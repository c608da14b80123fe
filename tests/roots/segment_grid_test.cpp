// The grid the OpenCL root-contact kernel walks (roots/segment_grid.hpp): every segment listed once, in the cell of
// its midpoint, a cell's segments in index order (the kernel sums a cell's contacts in that order, so the answer
// depends on it), and the same grid whatever the number of threads that build it.
#include "roots/segment_grid.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/parallel_for.hpp"

namespace heliostand::roots {
namespace {

// Trees' segment lists of different lengths (one empty), scattered over a few metres.
std::vector<std::vector<RootSegmentLine>> scattered_trees() {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> place(-3.0, 3.0), step(-0.3, 0.3);
  std::vector<std::vector<RootSegmentLine>> trees;
  for (int count : {40, 0, 7, 300, 1, 90}) {
    std::vector<RootSegmentLine> tree;
    for (int s = 0; s < count; ++s) {
      const glm::dvec3 start{place(random), place(random), -std::abs(place(random))};
      tree.push_back({start, start + glm::dvec3{step(random), step(random), step(random)}});
    }
    trees.push_back(std::move(tree));
  }
  return trees;
}

SegmentList list_of(const std::vector<std::vector<RootSegmentLine>>& trees) {
  SegmentList list;
  for (const auto& tree : trees) list.append(std::span<const RootSegmentLine>(tree));
  return list;
}

struct SegmentGridTest : ::testing::Test {
  ~SegmentGridTest() override { set_worker_threads(0); }
};

TEST_F(SegmentGridTest, ListsEverySegmentOnceInItsMidpointsCellInIndexOrder) {
  const auto trees = scattered_trees();
  const SegmentList segments = list_of(trees);
  const SegmentGrid grid = SegmentGrid::build(segments, 0.2);

  glm::dvec3 low(1e9), high(-1e9);
  double longest_half = 0.0;
  segments.for_each([&](std::size_t, const glm::dvec3& start, const glm::dvec3& end) {
    low = glm::min(low, 0.5 * (start + end));
    high = glm::max(high, 0.5 * (start + end));
    longest_half = std::max(longest_half, 0.5 * glm::length(end - start));
  });
  EXPECT_EQ(grid.origin, low);
  EXPECT_EQ(grid.longest_half_m, longest_half);
  EXPECT_DOUBLE_EQ(grid.cell_size_m, 0.5 * (0.2 + longest_half));

  const std::size_t cells = static_cast<std::size_t>(grid.dims.x) * grid.dims.y * grid.dims.z;
  ASSERT_EQ(grid.cell_start.size(), cells + 1);
  ASSERT_EQ(grid.cell_segments.size(), segments.size());
  std::vector<int> listed(segments.size(), 0);
  for (std::size_t c = 0; c < cells; ++c)
    for (int k = grid.cell_start[c]; k < grid.cell_start[c + 1]; ++k) {
      const auto s = static_cast<std::size_t>(grid.cell_segments[k]);
      ++listed[s];
      EXPECT_EQ(grid.cell_index(grid.cell_of(0.5 * (segments[s].start + segments[s].end))), c) << "segment " << s;
      if (k > grid.cell_start[c]) EXPECT_LT(grid.cell_segments[k - 1], grid.cell_segments[k]) << "cell " << c;
    }
  for (std::size_t s = 0; s < listed.size(); ++s) EXPECT_EQ(listed[s], 1) << "segment " << s;
}

TEST_F(SegmentGridTest, TheSameGridOnAnyNumberOfThreads) {
  const auto trees = scattered_trees();
  const SegmentList segments = list_of(trees);
  set_worker_threads(1);
  const SegmentGrid alone = SegmentGrid::build(segments, 0.2);
  for (unsigned threads : {2u, 3u, 8u}) {
    set_worker_threads(threads);
    const SegmentGrid grid = SegmentGrid::build(segments, 0.2);
    EXPECT_EQ(grid.origin, alone.origin) << threads;
    EXPECT_EQ(grid.dims, alone.dims) << threads;
    EXPECT_EQ(grid.cell_size_m, alone.cell_size_m) << threads;
    EXPECT_EQ(grid.cell_start, alone.cell_start) << threads;
    EXPECT_EQ(grid.cell_segments, alone.cell_segments) << threads;
  }
}

TEST_F(SegmentGridTest, NoSegmentsGiveOneEmptyCellAtTheOrigin) {
  const std::vector<std::vector<RootSegmentLine>> trees(3);
  const SegmentGrid grid = SegmentGrid::build(list_of(trees), 0.2);
  EXPECT_EQ(grid.origin, glm::dvec3(0.0));
  EXPECT_EQ(grid.dims, glm::ivec3(1));
  EXPECT_EQ(grid.longest_half_m, 0.0);
  EXPECT_EQ(grid.cell_start, std::vector<int>({0, 0}));
  EXPECT_TRUE(grid.cell_segments.empty());
}

}  // namespace
}  // namespace heliostand::roots
