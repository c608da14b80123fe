// The OpenCL culled kernel's tile scan on a CPU and elsewhere (only in a build with OpenCL: it names the device type).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>

#include <glm/geometric.hpp>

#include "compute/opencl_context.hpp"
#include "compute/opencl_test_backend.hpp"
#include "light/celestial_sphere.hpp"
#include "light/opencl_light_solver.hpp"
#include "light/reference_light_solver.hpp"
#include "light_test_stands.hpp"

namespace heliostand {
namespace {

// The tile scan finds the windows of two batches of eight near occluders at a time on a CPU and of one batch
// elsewhere (opencl_light_solver.cpp, scan_batches; cl/light.cl, shade_by_tile_candidates), then shades the rest a
// batch at a time. The same device called a GPU must give the same light bit for bit, on a stand whose receivers hold
// from fewer than two batches of near occluders to more than four, and both the reference's.
TEST(LightScanBatches, OneOrTwoBatchesAtATimeGiveTheSameLightBitForBit) {
  const auto backend = compute::opencl_backend_for_test();
  if (!backend) GTEST_SKIP() << "no OpenCL device";
  LightParameters p;
  p.exact = false;
  p.plot_x_max = p.plot_y_max = 4.0;
  p.cutoff_m = 1.3;
  p.far_field_cell_m = 0.5;
  p.transmittance = 0.6;
  const CelestialSphere sky(p);
  const auto balls = testing::random_stand(300, 4.0, 0.08, 0.25, 9, sky, false);
  std::size_t fewest = balls.size(), most = 0;
  for (const LeafBall& receiver : balls) {
    std::size_t near = 0;
    for (const LeafBall& ball : balls) near += glm::length(ball.centre - receiver.centre) <= p.cutoff_m;
    fewest = std::min(fewest, near - 1), most = std::max(most, near - 1);
  }
  EXPECT_LT(fewest, 16u);  // a receiver that never fills two batches
  EXPECT_GT(most, 33u);    // and one that fills them twice, and more
  compute::OpenCLContext cpu = *backend->opencl(), gpu = cpu;
  cpu.type = CL_DEVICE_TYPE_CPU;
  gpu.type = CL_DEVICE_TYPE_GPU;
  const auto two = OpenCLLightSolver(p, cpu).solve(balls);
  const auto one = OpenCLLightSolver(p, gpu).solve(balls);
  const auto expected = ReferenceLightSolver(p).solve(balls);
  ASSERT_EQ(two.size(), balls.size());
  ASSERT_EQ(one.size(), balls.size());
  double lowest = 1;
  for (std::size_t k = 0; k < balls.size(); ++k) {
    EXPECT_EQ(one[k].light, two[k].light) << "ball " << k;
    EXPECT_EQ(one[k].vector, two[k].vector) << "ball " << k;
    EXPECT_NEAR(two[k].light, expected[k].light, 1e-4) << "ball " << k;
    lowest = std::min(lowest, expected[k].light);
  }
  EXPECT_LT(lowest, 0.8);  // there is shade to get right
}

}  // namespace
}  // namespace heliostand
