// The OpenCL root-contact field against the reference on grown root systems of several trees (float on
// the device, double in the reference). Stated tolerance: per apex, the same number of contacts and
// every component of Vt within 1e-3 (a sum of up to ~100 unit vectors in float) and of Vw within 1e-4
// (16 probes of moisture ≤ 1). An apex with a segment within 1e-5 m of its sphere's surface (or 1e-6 m of the
// touching distance) may disagree on contacts: there float and double may legitimately disagree on "inside".
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "compute/opencl_test_backend.hpp"
#include "grown_root_stand.hpp"
#include "roots/make_root_field_solver.hpp"
#include "roots/reference_root_field_solver.hpp"
#include "rng/random_stream.hpp"
#include "roots/root_growth.hpp"

namespace heliostand::roots {
namespace {

using test_stands::GrownStand;

// Whether a segment lies within 1e-5 m of the apex's perception sphere or of the touching distance, where float and
// double may legitimately disagree on "inside".
bool on_the_edge(const RootTipQuery& tip, std::span<const RootSegmentLine> segments) {
  return std::any_of(segments.begin(), segments.end(), [&](const RootSegmentLine& segment) {
    const double distance = glm::length(nearest_point_on_segment(tip.position, segment) - tip.position);
    return std::abs(distance - tip.perception_radius_m) < 1e-5 || std::abs(distance - touching_distance_m) < 1e-6;
  });
}

// Null only where there is no OpenCL device; a kernel that does not build throws (the test fails).
std::unique_ptr<RootFieldSolver> make_opencl_or_null() {
  const auto device = compute::opencl_backend_for_test();
  return device ? make_root_field_solver(*device) : nullptr;
}

// Every apex's answer the reference's within the stated tolerances, but where a segment lies on the edge of its sphere
// (there only the moisture pull, which no edge moves, must agree); nearly every apex compared, and half of those with
// contacts (the comparison is not vacuous).
void expect_the_reference_within_tolerance(const std::vector<RootFieldSample>& actual,
                                           const std::vector<RootFieldSample>& expected,
                                           std::span<const RootTipQuery> tips,
                                           std::span<const RootSegmentLine> segments) {
  ASSERT_EQ(actual.size(), expected.size());
  int compared = 0, with_contacts = 0;
  for (std::size_t t = 0; t < tips.size(); ++t) {
    for (int axis = 0; axis < 3; ++axis)
      ASSERT_NEAR(actual[t].moisture_pull[axis], expected[t].moisture_pull[axis], 1e-4) << "apex " << t;
    bool agree = actual[t].contacts == expected[t].contacts;
    for (int axis = 0; axis < 3; ++axis)
      agree = agree && std::abs(actual[t].contact_avoidance[axis] - expected[t].contact_avoidance[axis]) <= 1e-3;
    if (!agree) {
      ASSERT_TRUE(on_the_edge(tips[t], segments))
          << "apex " << t << ": " << actual[t].contacts << " contacts, the reference " << expected[t].contacts;
      continue;
    }
    ++compared;
    if (expected[t].contacts > 0) ++with_contacts;
  }
  EXPECT_GT(compared, static_cast<int>(0.99 * tips.size()));
  EXPECT_GT(with_contacts, compared / 2);
}

// Every apex's answer the same, bit for bit, and a quarter of them with contacts (the comparison is not vacuous).
void expect_the_same_bit_for_bit(const std::vector<RootFieldSample>& actual, const std::vector<RootFieldSample>& alone) {
  ASSERT_EQ(actual.size(), alone.size());
  int with_contacts = 0;
  for (std::size_t t = 0; t < alone.size(); ++t) {
    ASSERT_EQ(actual[t].contacts, alone[t].contacts) << "apex " << t;
    for (int axis = 0; axis < 3; ++axis) {
      ASSERT_EQ(actual[t].contact_avoidance[axis], alone[t].contact_avoidance[axis]) << "apex " << t;
      ASSERT_EQ(actual[t].moisture_pull[axis], alone[t].moisture_pull[axis]) << "apex " << t;
    }
    if (alone[t].contacts > 0) ++with_contacts;
  }
  EXPECT_GT(with_contacts, static_cast<int>(alone.size() / 4));
}

TEST(OpenCLRootFieldSolver, MatchesTheReferenceOnGrownRootSystems) {
  auto opencl = make_opencl_or_null();
  if (!opencl) GTEST_SKIP() << "no OpenCL device";
  ReferenceRootFieldSolver reference;
  for (std::uint64_t seed : {1u, 2u}) {
    GrownStand stand = test_stands::grown_stand(10, seed);
    const test_stands::ApexQueries queries = test_stands::apices_at_every_segment_end(stand, seed);
    const StandSegments& segments = queries.segments;
    const std::vector<RootTipQuery>& tips = queries.tips;
    ASSERT_GT(tips.size(), 500u);
    const RootFieldInput input = queries.input(stand.soil);
    expect_the_reference_within_tolerance(opencl->solve(input), reference.solve(input), tips, segments.lines);
  }
}

TEST(OpenCLRootFieldSolver, GrowsTheSameRootSystemsAsTheReference) {
  auto opencl = make_opencl_or_null();
  if (!opencl) GTEST_SKIP() << "no OpenCL device";
  ReferenceRootFieldSolver reference;
  auto grow_with = [](RootFieldSolver& solver) {
    GrownStand stand;
    stand.soil.fill_gradient(SoilField::moisture, 0, 1.0, 0.1);
    for (int t = 0; t < 2; ++t) stand.trees.emplace_back(t, glm::dvec3(-0.5 + t, 0.0, 0.0), tap_rooted_conifer(), 0);
    std::vector<RootSystem*> pointers{&stand.trees[0], &stand.trees[1]};
    for (int year = 1; year <= 6; ++year) grow_roots(pointers, stand.soil, solver, year, 5);
    return stand;
  };
  const GrownStand a = grow_with(reference), b = grow_with(*opencl);
  for (std::size_t t = 0; t < a.trees.size(); ++t) {
    const auto sa = a.trees[t].segments(), sb = b.trees[t].segments();
    ASSERT_EQ(sa.size(), sb.size());  // branching never depends on the backend
    double worst = 0.0;
    for (std::size_t s = 0; s < sa.size(); ++s) worst = std::max(worst, glm::length(sa[s].end - sb[s].end));
    EXPECT_LT(worst, 1e-3) << "tree " << t;  // float directions, compounded over 6 years
  }
}

// Two stands of grown roots, one of three trees and one of ten, with apices at every segment end: a year and a larger
// one for the solver's kept state.
struct SmallAndLargeStands {
  GrownStand small = test_stands::grown_stand(4, 2), large = test_stands::grown_stand(10, 1);
  test_stands::ApexQueries small_queries, large_queries;
  SmallAndLargeStands() {
    small.trees.pop_back();
    small_queries = test_stands::apices_at_every_segment_end(small, 2);
    large_queries = test_stands::apices_at_every_segment_end(large, 1);
  }
};

// One solver serves every year of a run, and its kernel keeps the arguments one year set until the next sets them
// again. A year with fewer segments, cells, apices and soil vertices than the year before, in another soil (another
// frame origin), must use nothing that year set: its answers are those of a solver that never saw the larger year,
// bit for bit.
TEST(OpenCLRootFieldSolver, AYearAfterALargerOneAnswersAsAFreshSolverDoes) {
  auto kept = make_opencl_or_null();
  if (!kept) GTEST_SKIP() << "no OpenCL device";
  auto fresh = make_opencl_or_null();
  ASSERT_TRUE(fresh);
  SmallAndLargeStands stands;
  ASSERT_GT(stands.large_queries.segments.lines.size(), 2 * stands.small_queries.segments.lines.size());
  SoilGrid small_soil{{{-3.0, -3.0, -2.0}, 0.25, {24, 24, 8}}, 1.0, 0.5};
  small_soil.fill_gradient(SoilField::moisture, 0, 0.9, 0.2);
  kept->solve(stands.large_queries.input(stands.large.soil));
  const auto after_large = kept->solve(stands.small_queries.input(small_soil));
  const auto alone = fresh->solve(stands.small_queries.input(small_soil));
  expect_the_same_bit_for_bit(after_large, alone);
}

// The solver keeps its buffers from one year to the next and from one query to the next, growing them when a year
// has more segments or a query more apices than any before. A year larger than the last, queried first with a few
// apices and then with all of them, must answer as a fresh solver does, bit for bit.
TEST(OpenCLRootFieldSolver, AYearLargerThanTheLastAndALargerQueryAnswerAsAFreshSolverDoes) {
  auto kept = make_opencl_or_null();
  if (!kept) GTEST_SKIP() << "no OpenCL device";
  auto fresh = make_opencl_or_null();
  ASSERT_TRUE(fresh);
  SmallAndLargeStands stands;
  ASSERT_GT(stands.large_queries.segments.lines.size(), 2 * stands.small_queries.segments.lines.size());
  kept->solve(stands.small_queries.input(stands.small.soil));

  const test_stands::ApexQueries& large_queries = stands.large_queries;
  const std::vector<RootTipQuery>& tips = large_queries.tips;
  RootFieldYear year;
  year.segments = SegmentList(large_queries.segments.lines);
  year.soil = &stands.large.soil;
  for (const RootTipQuery& tip : tips)  // as solve() sizes the grid
    year.widest_perception_radius_m = std::max(year.widest_perception_radius_m, tip.perception_radius_m);
  kept->begin_year(year);
  const std::size_t few = 7;
  kept->query(std::span(tips).first(few), std::span(large_queries.probes).first(few * large_queries.probes_per_tip),
              large_queries.probes_per_tip);
  const auto after_few = kept->query(tips, large_queries.probes, large_queries.probes_per_tip);
  kept->end_year();
  const auto alone = fresh->solve(large_queries.input(stands.large.soil));
  expect_the_same_bit_for_bit(after_few, alone);
}

// A year's segments reach the device 65 536 at a time (opencl_root_field.cpp, segments_per_upload), each part written
// at its own place in the kept buffers. A stand of more than two parts' worth of short segments, felt by apices spread
// over all of it, must be answered as the reference answers it (the stated tolerances of the first test).
TEST(OpenCLRootFieldSolver, SegmentsWrittenInPartsAnswerAsTheReferenceDoes) {
  auto opencl = make_opencl_or_null();
  if (!opencl) GTEST_SKIP() << "no OpenCL device";
  RandomStream random(17, {3});
  auto anywhere = [&] {
    return glm::dvec3(random.uniform(0.0, 6.0), random.uniform(0.0, 6.0), random.uniform(-1.5, 0.0));
  };
  std::vector<RootSegmentLine> segments(150'000);
  for (RootSegmentLine& segment : segments) {
    segment.start = anywhere();
    const glm::dvec3 step(random.uniform(-1.0, 1.0), random.uniform(-1.0, 1.0), random.uniform(-1.0, 1.0));
    segment.end = segment.start + 0.1 * step;
  }
  std::vector<RootTipQuery> tips(3'000);
  for (RootTipQuery& tip : tips) {
    tip.position = anywhere();
    tip.perception_radius_m = random.uniform(0.05, 0.15);
  }
  tips[0].excluded[0] = 7, tips[0].excluded[1] = 70'000;  // exclusions on both sides of a part's end
  SoilGrid soil{{{-0.5, -0.5, -2.0}, 0.25, {29, 29, 10}}, 1.0, 0.5};
  soil.fill_gradient(SoilField::moisture, 0, 0.9, 0.2);
  const int probes_per_tip = 4;
  std::vector<glm::dvec3> probes;
  for (std::size_t t = 0; t < tips.size(); ++t)
    for (const glm::dvec3& probe : draw_moisture_probes(random, probes_per_tip)) probes.push_back(probe);
  const RootFieldInput input{segments, tips, probes, probes_per_tip, &soil};
  expect_the_reference_within_tolerance(opencl->solve(input), ReferenceRootFieldSolver().solve(input), tips, segments);
}

}  // namespace
}  // namespace heliostand::roots
