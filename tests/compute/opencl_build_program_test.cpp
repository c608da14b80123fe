// Every kernel is built through compute::build_program: a kernel that does not compile is an error that carries
// the compiler's log — a failure, never a skip — and constants given as build options reach the kernel as the
// C++ values.
#include "compute/opencl_context.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "compute/kernel_files_override.hpp"
#include "compute/kernel_options.hpp"
#include "compute/opencl_test_backend.hpp"
#include "light/light_sum.hpp"
#include "light/make_light_solver.hpp"
#include "roots/make_root_field_solver.hpp"
#include "roots/root_field_solver.hpp"

namespace heliostand::compute {
namespace {

std::string build_error(const OpenCLContext& device, const std::string& source) {
  try {
    build_program(device, source, "");
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "";
}

TEST(BuildProgram, AKernelThatDoesNotCompileThrowsWithTheBuildLog) {
  const auto backend = opencl_backend_for_test();
  if (!backend) GTEST_SKIP() << "no OpenCL device";
  const std::string message =
      build_error(*backend->opencl(), "kernel void broken(global float* out) { out[0] = undeclared_value; }\n");
  ASSERT_FALSE(message.empty()) << "a kernel using an undeclared name was built";
  EXPECT_NE(message.find("OpenCL kernel build failed"), std::string::npos) << message;
  EXPECT_NE(message.find("undeclared_value"), std::string::npos) << "no compiler log in: " << message;
}

TEST(BuildProgram, SolversWhoseKernelDoesNotCompileThrow) {
  const auto backend = opencl_backend_for_test();
  if (!backend) GTEST_SKIP() << "no OpenCL device";
  const std::string broken_source = "kernel void broken( {\n";
  const testing::KernelFilesOverride broken("broken_kernels",
                                            {{"light.cl", broken_source}, {"roots.cl", broken_source}});
  EXPECT_THROW(make_light_solver(*backend, LightParameters{}), std::runtime_error);
  EXPECT_THROW(roots::make_root_field_solver(*backend), std::runtime_error);
}

TEST(BuildProgram, BuildOptionConstantsAreTheCppValuesInFloat) {
  const auto backend = opencl_backend_for_test();
  if (!backend) GTEST_SKIP() << "no OpenCL device";
  const OpenCLContext& device = *backend->opencl();
  const auto options = KernelOptions()
                           .define("BALANCED_LIGHT_FRACTION", balanced_light_fraction)
                           .define("TOUCHING_DISTANCE", roots::touching_distance_m)
                           .define("NEGATIVE", -0.1)
                           .define("BANDS", 16);
  cl::Program program = build_program(device,
                                      "kernel void constants(global float* f, global int* n) {\n"
                                      "  f[0] = BALANCED_LIGHT_FRACTION; f[1] = TOUCHING_DISTANCE;\n"
                                      "  f[2] = 1.0f-NEGATIVE; n[0] = BANDS;\n"
                                      "}\n",
                                      options.text());
  cl::Buffer floats(device.context, CL_MEM_WRITE_ONLY, 3 * sizeof(float));
  cl::Buffer integers(device.context, CL_MEM_WRITE_ONLY, sizeof(int));
  cl::Kernel kernel(program, "constants");
  kernel.setArg(0, floats);
  kernel.setArg(1, integers);
  device.queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(1), cl::NullRange);
  float f[3] = {};
  int n = 0;
  device.queue.enqueueReadBuffer(floats, CL_TRUE, 0, sizeof f, f);
  device.queue.enqueueReadBuffer(integers, CL_TRUE, 0, sizeof n, &n);
  EXPECT_EQ(f[0], static_cast<float>(balanced_light_fraction));
  EXPECT_EQ(f[1], static_cast<float>(roots::touching_distance_m));
  EXPECT_EQ(f[2], 1.0f - -0.1f);
  EXPECT_EQ(n, 16);
}

}  // namespace
}  // namespace heliostand::compute
