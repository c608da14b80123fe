// Every kernel is built through compute::build_program: a kernel that does not compile is an error that carries
// the compiler's log — a failure, never a skip.
#include "compute/opencl_context.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "compute/opencl_test_backend.hpp"
#include "light/make_light_solver.hpp"
#include "roots/make_root_field_solver.hpp"

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

// HELIOSTAND_KERNEL_DIR pointing at broken copies of the solvers' kernel files for one scope.
class BrokenKernelFiles {
 public:
  BrokenKernelFiles() {
    for (const char* file : {"light.cl", "roots.cl"}) std::ofstream(dir_ / file) << "kernel void broken( {\n";
    ::setenv("HELIOSTAND_KERNEL_DIR", dir_.c_str(), 1);
  }
  ~BrokenKernelFiles() {
    ::unsetenv("HELIOSTAND_KERNEL_DIR");
    std::filesystem::remove_all(dir_);
  }

 private:
  std::filesystem::path dir_ = [] {
    auto dir = std::filesystem::temp_directory_path() / ("heliostand_broken_kernels_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir;
  }();
};

TEST(BuildProgram, SolversWhoseKernelDoesNotCompileThrow) {
  const auto backend = opencl_backend_for_test();
  if (!backend) GTEST_SKIP() << "no OpenCL device";
  const BrokenKernelFiles broken;
  EXPECT_THROW(make_light_solver(*backend, LightParameters{}), std::runtime_error);
  EXPECT_THROW(roots::make_root_field_solver(*backend), std::runtime_error);
}

}  // namespace
}  // namespace heliostand::compute
