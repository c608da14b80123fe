// The OpenCL solver keeps its far-field table's buffers on the device from one solve to the next, the sweep's layout
// and the one by cell (a run solves every year; on a CPU device writing into a fresh buffer took 3-4 times as long as
// into a used one): what it lights must not depend on what it lit before. A sweep that left one layer of a reused
// buffer as the stand before had it fails here on every stand after the first.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "compute/opencl_test_backend.hpp"
#include "light/celestial_sphere.hpp"
#include "light/opencl_light_solver.hpp"
#include "light_test_stands.hpp"

namespace heliostand {
namespace {

LightParameters culled_with_far_field() {
  LightParameters p;
  p.exact = false;
  p.far_field = true;
  p.cutoff_m = 1.5;  // most of each stand beyond the cut-off: the far field decides much of the light
  p.far_field_cell_m = 0.5;
  return p;
}

void expect_same_light(const std::vector<LightSample>& reused, const std::vector<LightSample>& fresh) {
  ASSERT_EQ(reused.size(), fresh.size());
  for (std::size_t i = 0; i < fresh.size(); ++i) {
    EXPECT_EQ(reused[i].light, fresh[i].light) << "ball " << i;
    EXPECT_EQ(reused[i].vector, fresh[i].vector) << "ball " << i;
  }
}

TEST(OpenCLFarFieldTable, ASolverLightsEachStandAsAFreshSolverWould) {
  const auto backend = compute::opencl_backend_for_test();
  if (!backend) GTEST_SKIP() << "no OpenCL device";
  const LightParameters p = culled_with_far_field();
  const CelestialSphere sky(p);
  // A stand, a smaller one (its table fits in the first's buffer) and a larger one (it does not): different grids.
  const std::vector<std::vector<LeafBall>> stands{testing::random_stand(400, 6.0, 0.1, 0.3, 11, sky, false),
                                                  testing::random_stand(150, 3.0, 0.1, 0.3, 12, sky, false),
                                                  testing::random_stand(900, 9.0, 0.1, 0.3, 13, sky, false)};
  OpenCLLightSolver reused(p, *backend->opencl());
  for (const auto& balls : stands) {
    OpenCLLightSolver fresh(p, *backend->opencl());
    expect_same_light(reused.solve(balls), fresh.solve(balls));
  }
}

// Only the cells some receiver reads are laid out by cell (cl/far_field.cl, far_field_mark_read), so a solve for a
// few receivers lays out few. Each receiver must still read its own cells as the whole stand's solve does, whatever
// an earlier solve left in the others, and a whole solve after the few must lay out every cell again. Marking the
// cells of the first balls rather than of the receivers fails here alone (the whole-stand tests cannot see it), and
// so does marking only the lower corner of each axis; marking none fails the tests against the reference solver.
TEST(OpenCLFarFieldTable, AFewReceiversAreLitAsTheWholeStandLightsThem) {
  const auto backend = compute::opencl_backend_for_test();
  if (!backend) GTEST_SKIP() << "no OpenCL device";
  const LightParameters p = culled_with_far_field();
  const CelestialSphere sky(p);
  const auto before = testing::random_stand(400, 6.0, 0.1, 0.3, 11, sky, false);
  const auto stand = testing::random_stand(900, 9.0, 0.1, 0.3, 13, sky, false);
  const std::vector<LightSample> whole = OpenCLLightSolver(p, *backend->opencl()).solve(stand);
  std::vector<std::uint32_t> few;
  for (std::uint32_t i = 0; i < stand.size(); i += 37) few.push_back(i);
  OpenCLLightSolver reused(p, *backend->opencl());
  (void)reused.solve(before);
  const std::vector<LightSample> lit = reused.solve_for(stand, few);
  ASSERT_EQ(lit.size(), few.size());
  for (std::size_t k = 0; k < few.size(); ++k) {
    EXPECT_EQ(lit[k].light, whole[few[k]].light) << "ball " << few[k];
    EXPECT_EQ(lit[k].vector, whole[few[k]].vector) << "ball " << few[k];
  }
  expect_same_light(reused.solve(stand), whole);
}

}  // namespace
}  // namespace heliostand
