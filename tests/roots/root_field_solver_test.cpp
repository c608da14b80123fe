// One test body for every RootFieldSolver backend (the OpenMM pattern): hand-computed cases that each
// implementation must reproduce on its own. Backend-vs-reference agreement on random root systems is in
// opencl_root_field_solver_test.cpp.
#include "roots/root_field_solver.hpp"

#include <gtest/gtest.h>

#include <memory>

#include <glm/geometric.hpp>

#include "compute/opencl_test_backend.hpp"
#include "geometry/vector_checks.hpp"
#include "roots/make_root_field_solver.hpp"

namespace heliostand::roots {
namespace {

struct Backend {
  std::string label;
  bool opencl = false;
};
void PrintTo(const Backend& backend, std::ostream* out) { *out << backend.label; }

class RootFieldSolverContract : public ::testing::TestWithParam<Backend> {
 protected:
  // Skipped only where there is no OpenCL device: a kernel that fails to build fails the test.
  void SetUp() override {
    std::optional<compute::ComputeBackend> backend = compute::ComputeBackend::reference();
    if (GetParam().opencl) {
      backend = compute::opencl_backend_for_test();
      if (!backend) GTEST_SKIP() << "no OpenCL device";
    }
    solver_ = make_root_field_solver(*backend);
  }
  // Contacts of one apex among `segments` (float on the device: compare to 1e-5).
  RootFieldSample contact(std::vector<RootSegmentLine> segments, RootTipQuery tip) {
    RootFieldInput input;
    input.segments = segments;
    input.tips = std::span(&tip, 1);
    return solver_->solve(input).at(0);
  }
  std::unique_ptr<RootFieldSolver> solver_;
};

constexpr double tolerance = 1e-5;

void expect_near(const glm::dvec3& actual, const glm::dvec3& expected) {
  testing::expect_near(actual, expected, tolerance);
}

RootTipQuery apex_at(glm::dvec3 position, double radius = 0.3) {
  RootTipQuery tip;
  tip.position = position;
  tip.perception_radius_m = radius;
  return tip;
}

TEST_P(RootFieldSolverContract, ATipBesideOneSegmentIsPushedStraightAwayFromIt) {
  // Segment along x at y = 0; the apex 0.1 m north of its middle: Vt points north, perpendicular to it.
  const RootFieldSample sample = contact({{{-1.0, 0.0, -1.0}, {1.0, 0.0, -1.0}}}, apex_at({0.3, 0.1, -1.0}));
  EXPECT_EQ(sample.contacts, 1);
  expect_near(sample.contact_avoidance, {0.0, 1.0, 0.0});
}

TEST_P(RootFieldSolverContract, TheNearestPointMayBeASegmentEnd) {
  // The segment starts 0.2 m east of the apex and runs east: felt in the direction of its start.
  const RootFieldSample sample = contact({{{0.2, 0.0, -1.0}, {1.0, 0.0, -1.0}}}, apex_at({0.0, 0.0, -1.0}));
  EXPECT_EQ(sample.contacts, 1);
  expect_near(sample.contact_avoidance, {-1.0, 0.0, 0.0});
}

TEST_P(RootFieldSolverContract, SymmetricNeighboursCancel) {
  const RootFieldSample sample = contact({{{-1.0, 0.1, -1.0}, {1.0, 0.1, -1.0}},
                                          {{-1.0, -0.1, -1.0}, {1.0, -0.1, -1.0}},
                                          {{0.0, 0.0, -0.8}, {0.0, 0.0, -0.7}},
                                          {{0.0, 0.0, -1.2}, {0.0, 0.0, -1.3}}},
                                         apex_at({0.0, 0.0, -1.0}));
  EXPECT_EQ(sample.contacts, 4);
  expect_near(sample.contact_avoidance, {0.0, 0.0, 0.0});
}

TEST_P(RootFieldSolverContract, SeveralNeighboursAddUnitDirections) {
  // One segment south (felt northward), one east (felt westward), one far away (not felt).
  const RootFieldSample sample = contact({{{-1.0, -0.2, 0.0}, {1.0, -0.2, 0.0}},
                                          {{0.05, -1.0, 0.0}, {0.05, 1.0, 0.0}},
                                          {{5.0, 5.0, 0.0}, {5.0, 5.2, 0.0}}},
                                         apex_at({0.0, 0.0, 0.0}));
  EXPECT_EQ(sample.contacts, 2);
  expect_near(sample.contact_avoidance, {-1.0, 1.0, 0.0});
}

// The touching distance is the C++ constant on both backends (the kernel gets it as a build option): a segment
// half of it away is not felt, one three times it away is.
TEST_P(RootFieldSolverContract, ASegmentTouchingTheApexIsNotFelt) {
  const double touching = touching_distance_m;
  const RootFieldSample sample = contact({{{0.0, 0.5 * touching, 0.0}, {0.0, 0.5 * touching, -0.2}},
                                          {{0.0, -3.0 * touching, 0.0}, {0.0, -3.0 * touching, -0.2}}},
                                         apex_at({0.0, 0.0, 0.0}));
  EXPECT_EQ(sample.contacts, 1);
  expect_near(sample.contact_avoidance, {0.0, 1.0, 0.0});
}

TEST_P(RootFieldSolverContract, OnlyInsideThePerceptionSphere) {
  const std::vector<RootSegmentLine> segments{{{-1.0, 0.35, 0.0}, {1.0, 0.35, 0.0}}};
  EXPECT_EQ(contact(segments, apex_at({0.0, 0.0, 0.0}, 0.3)).contacts, 0);
  EXPECT_EQ(contact(segments, apex_at({0.0, 0.0, 0.0}, 0.4)).contacts, 1);
}

TEST_P(RootFieldSolverContract, TheApexFeelsNeitherItsOwnSegmentNorItsParent) {
  // Own segment ends at the apex, the parent runs into it, a sibling-like root lies 0.1 m west.
  const std::vector<RootSegmentLine> segments{{{0.0, 0.0, -0.5}, {0.0, 0.0, -0.75}},   // parent
                                              {{0.0, 0.0, -0.75}, {0.0, 0.0, -1.0}},  // own
                                              {{-0.1, -1.0, -1.0}, {-0.1, 1.0, -1.0}}};
  RootTipQuery tip = apex_at({0.0, 0.0, -1.0});
  tip.excluded[0] = 1;
  tip.excluded[1] = 0;
  const RootFieldSample sample = contact(segments, tip);
  EXPECT_EQ(sample.contacts, 1);
  expect_near(sample.contact_avoidance, {1.0, 0.0, 0.0});
}

TEST_P(RootFieldSolverContract, MoistureProbesPullTowardTheWetSide) {
  // Moisture 1 − x/4 over 0 ≤ x ≤ 4; probes ±x at the sphere's surface, R = 0.5, apex at x = 2:
  // Vw = (+1)·m(2.5) + (−1)·m(1.5) = 0.375 − 0.625 = −0.25 along x.
  SoilGrid soil({{0.0, 0.0, -2.0}, 0.5, {8, 4, 4}}, 1.0, 0.5);
  soil.fill_gradient(SoilField::moisture, 0, 1.0, 0.0);
  const std::vector<glm::dvec3> probes{{1.0, 0.0, 0.0}, {-1.0, 0.0, 0.0}, {0.0, 0.5, 0.0}, {0.0, -0.5, 0.0}};
  const RootTipQuery tip = apex_at({2.0, 1.0, -1.0}, 0.5);
  RootFieldInput input;
  input.tips = std::span(&tip, 1);
  input.probes = probes;
  input.probes_per_tip = 4;
  input.soil = &soil;
  const RootFieldSample sample = solver_->solve(input).at(0);
  expect_near(sample.moisture_pull, {-0.25, 0.0, 0.0});
  EXPECT_EQ(sample.contacts, 0);

  soil.fill_uniform(SoilField::moisture, 0.7);  // antithetic probes in uniform soil: no pull
  expect_near(solver_->solve(input).at(0).moisture_pull, {0.0, 0.0, 0.0});
  input.soil = nullptr;  // no soil: no pull
  expect_near(solver_->solve(input).at(0).moisture_pull, {0.0, 0.0, 0.0});
}

TEST_P(RootFieldSolverContract, ManyTipsInOrderAndAnEmptyStand) {
  const std::vector<RootSegmentLine> segments{{{0.0, -1.0, 0.0}, {0.0, 1.0, 0.0}}};
  const std::vector<RootTipQuery> tips{apex_at({0.1, 0.0, 0.0}), apex_at({-0.2, 0.5, 0.0}), apex_at({3.0, 0.0, 0.0})};
  RootFieldInput input;
  input.segments = segments;
  input.tips = tips;
  const auto samples = solver_->solve(input);
  ASSERT_EQ(samples.size(), 3u);
  expect_near(samples[0].contact_avoidance, {1.0, 0.0, 0.0});
  expect_near(samples[1].contact_avoidance, {-1.0, 0.0, 0.0});
  EXPECT_EQ(samples[2].contacts, 0);
  input.segments = {};
  EXPECT_EQ(solver_->solve(input).at(0).contacts, 0);
  input.tips = {};
  EXPECT_TRUE(solver_->solve(input).empty());
}

INSTANTIATE_TEST_SUITE_P(Backends, RootFieldSolverContract,
                         ::testing::Values(Backend{"Reference", false}, Backend{"OpenCL", true}),
                         [](const ::testing::TestParamInfo<Backend>& info) { return info.param.label; });

}  // namespace
}  // namespace heliostand::roots
