// The structure that keeps the roots stage linear in segments (docs/performance.md, "The roots stage now"): the year's
// field looks at the trees' own segment lists instead of a copy, is begun once a year, and is queried a chunk of
// buds at a time without the answer depending on the chunk size. No timing here: only what is built, how often,
// and that the result is the same.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <vector>

#include "compute/opencl_test_backend.hpp"
#include "roots/make_root_field_solver.hpp"
#include "roots/reference_root_field_solver.hpp"
#include "roots/root_growth.hpp"

namespace heliostand::roots {
namespace {

TEST(SegmentList, ViewsTheTreesOwnSegmentsWithoutCopying) {
  std::vector<RootSegment> first(3), second(2);
  for (std::size_t i = 0; i < first.size(); ++i) first[i].end = {1.0 * i, 0.0, -1.0};
  for (std::size_t i = 0; i < second.size(); ++i) second[i].start = {0.0, 2.0 * i, 0.0};
  SegmentList list;
  list.append(std::span<const RootSegment>(first));
  list.append(std::span<const RootSegment>());  // a tree without segments takes no index
  list.append(std::span<const RootSegment>(second));
  ASSERT_EQ(list.size(), 5u);
  EXPECT_EQ(list.first_of_part(2), 3u);
  EXPECT_EQ(list[2].end, glm::dvec3(2.0, 0.0, -1.0));
  EXPECT_EQ(list[4].start, glm::dvec3(0.0, 2.0, 0.0));
  // A change to a tree's segment shows through the list: it holds no copy.
  second[1].start = {7.0, 7.0, 7.0};
  EXPECT_EQ(list[4].start, glm::dvec3(7.0, 7.0, 7.0));
  std::size_t visited = 0;
  list.for_each([&](std::size_t i, const glm::dvec3& start, const glm::dvec3& end) {
    EXPECT_EQ(i, visited++);
    EXPECT_EQ(start, list[i].start);
    EXPECT_EQ(end, list[i].end);
  });
  EXPECT_EQ(visited, 5u);
}

// Many trees, some without segments (their parts share a first index with the next): every index finds its own
// segment, as the visit in order does. The segment grid's gather asks for them in cell order, out of index order.
TEST(SegmentList, FindsEverySegmentAmongManyPartsSomeEmpty) {
  std::vector<std::vector<RootSegment>> trees(61);
  for (std::size_t t = 0; t < trees.size(); ++t) {
    trees[t].resize(t % 4 == 1 ? 0 : (t * 7) % 13 + 1);
    for (std::size_t k = 0; k < trees[t].size(); ++k) {
      trees[t][k].start = {1.0 * t, 1.0 * k, 0.0};
      trees[t][k].end = {1.0 * t, 1.0 * k, -1.0};
    }
  }
  trees.back().clear();  // an empty last part too
  SegmentList list;
  for (const auto& tree : trees) list.append(std::span<const RootSegment>(tree));
  std::vector<glm::dvec3> starts;
  list.for_each([&](std::size_t, const glm::dvec3& start, const glm::dvec3&) { starts.push_back(start); });
  ASSERT_EQ(starts.size(), list.size());
  for (std::size_t i = list.size(); i-- > 0;) {  // from the last back, out of the visit's order
    EXPECT_EQ(list[i].start, starts[i]) << "segment " << i;
    EXPECT_EQ(list[i].end, starts[i] + glm::dvec3(0.0, 0.0, -1.0)) << "segment " << i;
  }
}

// Passes everything to the reference solver and counts how the field is used.
class CountingSolver final : public RootFieldSolver {
 public:
  std::string name() const override { return "counting"; }
  void begin_year(const RootFieldYear& year) override {
    ++years_begun;
    segments_this_year = year.segments.size();
    parts_this_year = year.segments.part_count();
    reference.begin_year(year);
  }
  std::vector<RootFieldSample> query(std::span<const RootTipQuery> tips, std::span<const glm::dvec3> probes,
                                     int probes_per_tip) override {
    ++queries;
    tips_asked += tips.size();
    largest_query = std::max(largest_query, tips.size());
    return reference.query(tips, probes, probes_per_tip);
  }
  void end_year() override {
    ++years_ended;
    reference.end_year();
  }
  ReferenceRootFieldSolver reference;
  int years_begun = 0, years_ended = 0, queries = 0;
  std::size_t segments_this_year = 0, parts_this_year = 0, tips_asked = 0, largest_query = 0;
};

struct Stand {
  SoilGrid soil{{{-4.0, -4.0, -3.0}, 0.25, {32, 32, 12}}, 1.0, 0.5};
  std::vector<RootSystem> trees;
  std::vector<RootSystem*> pointers;
  Stand() {
    soil.fill_gradient(SoilField::moisture, 0, 1.0, 0.1);
    for (int t = 0; t < 3; ++t) trees.emplace_back(t, glm::dvec3(-1.0 + 1.0 * t, 0.3 * t, 0.0), tap_rooted_conifer(), 0);
    for (RootSystem& tree : trees) pointers.push_back(&tree);
  }
  std::size_t segments() const {
    std::size_t count = 0;
    for (const RootSystem& tree : trees) count += tree.segments().size();
    return count;
  }
};

TEST(GrowRoots, BeginsTheFieldOnceAYearAndAsksInChunksOfBuds) {
  Stand stand;
  CountingSolver solver;
  constexpr std::size_t chunk = 50;
  for (int year = 1; year <= 8; ++year) {
    const std::size_t segments_before = stand.segments();
    const int years_before = solver.years_begun, queries_before = solver.queries;
    const std::size_t tips_before = solver.tips_asked;
    const RootYearSummary summary = grow_roots(stand.pointers, stand.soil, solver, year, 3, chunk);
    EXPECT_EQ(solver.years_begun, years_before + 1) << "year " << year;
    EXPECT_EQ(solver.years_ended, solver.years_begun) << "nothing of the field is held between years";
    EXPECT_EQ(solver.segments_this_year, segments_before) << "year " << year;
    EXPECT_EQ(solver.parts_this_year, stand.trees.size()) << "one part per tree, not a gathered copy";
    const std::size_t buds = solver.tips_asked - tips_before;
    EXPECT_EQ(buds, static_cast<std::size_t>(summary.new_segments));
    EXPECT_EQ(static_cast<std::size_t>(solver.queries - queries_before), (buds + chunk - 1) / chunk) << "year " << year;
  }
  EXPECT_EQ(solver.largest_query, chunk);
}

// Grows the stand 8 years with `chunk` buds per query and returns every segment's end, tree after tree.
std::vector<glm::dvec3> grown_ends(RootFieldSolver& solver, std::size_t chunk) {
  Stand stand;
  for (int year = 1; year <= 8; ++year) {
    grow_roots(stand.pointers, stand.soil, solver, year, 11, chunk);
    stand.soil.recharge({});
  }
  std::vector<glm::dvec3> ends;
  for (const RootSystem& tree : stand.trees)
    for (const RootSegment& segment : tree.segments()) ends.push_back(segment.end);
  return ends;
}

void expect_chunking_changes_nothing(RootFieldSolver& solver) {
  const std::vector<glm::dvec3> whole = grown_ends(solver, default_buds_per_query);
  ASSERT_GT(whole.size(), 500u);
  for (std::size_t chunk : {std::size_t{1}, std::size_t{7}, std::size_t{100}}) {
    const std::vector<glm::dvec3> chunked = grown_ends(solver, chunk);
    ASSERT_EQ(chunked.size(), whole.size()) << chunk << " buds per query";
    for (std::size_t i = 0; i < whole.size(); ++i)
      ASSERT_EQ(chunked[i], whole[i]) << "segment " << i << ", " << chunk << " buds per query";  // bit for bit
  }
}

TEST(GrowRoots, TheChunkOfBudsPerQueryChangesNothingOnTheReference) {
  ReferenceRootFieldSolver solver;
  expect_chunking_changes_nothing(solver);
}

TEST(GrowRoots, TheChunkOfBudsPerQueryChangesNothingOnOpenCL) {
  const auto device = compute::opencl_backend_for_test();
  if (!device) GTEST_SKIP() << "no OpenCL device";
  const auto solver = make_root_field_solver(*device);
  expect_chunking_changes_nothing(*solver);
}

}  // namespace
}  // namespace heliostand::roots
