// The OpenCL solver checks its far-field cap against its device when it is made (light/far_field_buffers.hpp), with
// the figures the device reports. Without the check, a cap beyond the device's largest buffer is made here and
// fails only when a stand's table reaches it, at clCreateBuffer.
#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <vector>

#include "compute/opencl_context.hpp"
#include "compute/opencl_test_backend.hpp"
#include "light/celestial_sphere.hpp"
#include "light/far_field_buffers.hpp"
#include "light/opencl_light_solver.hpp"
#include "light_test_stands.hpp"

namespace heliostand {
namespace {

TEST(OpenCLFarFieldBuffers, TheBackendNamesTheMemoryItsDeviceReports) {
  const auto backend = compute::opencl_backend_for_test();
  if (!backend) GTEST_SKIP() << "no OpenCL device";
  const auto memory = backend->memory();
  ASSERT_TRUE(memory);
  const cl::Device& device = backend->opencl()->device;
  EXPECT_EQ(memory->buffer_bytes, device.getInfo<CL_DEVICE_MAX_MEM_ALLOC_SIZE>());
  EXPECT_EQ(memory->total_bytes, device.getInfo<CL_DEVICE_GLOBAL_MEM_SIZE>());
  EXPECT_EQ(compute::ComputeBackend::reference().memory(), std::nullopt);
}

TEST(OpenCLFarFieldBuffers, ACapTheDeviceCannotHoldIsRefusedWhenTheSolverIsMade) {
  const auto backend = compute::opencl_backend_for_test();
  if (!backend) GTEST_SKIP() << "no OpenCL device";
  LightParameters p;
  p.exact = false;
  p.cutoff_m = 1.5;
  p.far_field_cell_m = 0.5;
  p.far_field_table_mb = compute::whole_megabytes(backend->memory()->buffer_bytes) + 1;
  std::string reason;
  try {
    OpenCLLightSolver beyond(p, *backend->opencl());
  } catch (const FarFieldBeyondDevice& e) {
    reason = e.what();
  }
  ASSERT_FALSE(reason.empty()) << "a cap of " << p.far_field_table_mb << " MB was taken";
  std::smatch advised;
  ASSERT_TRUE(std::regex_search(reason, advised, std::regex("lower it to ([0-9]+) or less"))) << reason;

  // The exact light has no far field: the same cap is no concern of it.
  LightParameters exact = p;
  exact.exact = true;
  EXPECT_NO_THROW(OpenCLLightSolver(exact, *backend->opencl()));

  // At the advised cap the solver is made, and a stand whose table stays far below either cap is lit as at the
  // default cap (the cap bounds the buffers; it changes no answer until a table reaches it).
  LightParameters at_advised = p;
  at_advised.far_field_table_mb = std::stod(advised[1]);
  const CelestialSphere sky(p);
  const auto stand = testing::random_stand(300, 5.0, 0.1, 0.3, 21, sky, false);
  LightParameters at_default = p;
  at_default.far_field_table_mb = LightParameters{}.far_field_table_mb;
  const auto lit = OpenCLLightSolver(at_advised, *backend->opencl()).solve(stand);
  const auto lit_by_default = OpenCLLightSolver(at_default, *backend->opencl()).solve(stand);
  ASSERT_EQ(lit.size(), lit_by_default.size());
  for (std::size_t i = 0; i < lit.size(); ++i) EXPECT_EQ(lit[i].light, lit_by_default[i].light) << "ball " << i;
}

}  // namespace
}  // namespace heliostand
