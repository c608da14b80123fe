// One compute backend per run: chosen once from --device, and both solver factories (light and roots) put
// their solver on it.
#include "compute/compute_backend.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "compute/opencl_test_backend.hpp"
#include "light/make_light_solver.hpp"
#include "roots/make_root_field_solver.hpp"

namespace heliostand::compute {
namespace {

TEST(ComputeBackend, ReferenceRunsLightAndRootsOnThePlainCppSolvers) {
  const auto backend = ComputeBackend::open(DeviceChoice::parse("reference"));
  EXPECT_FALSE(backend.is_opencl());
  EXPECT_EQ(backend.name(), "reference");
  EXPECT_EQ(make_light_solver(backend, LightParameters{})->name(), "reference");
  EXPECT_EQ(roots::make_root_field_solver(backend)->name(), "reference");
}

TEST(ComputeBackend, OpenCLRunsLightAndRootsOnTheSameDevice) {
  const auto backend = opencl_backend_for_test();
  if (!backend) GTEST_SKIP() << "no OpenCL device";
  EXPECT_TRUE(backend->is_opencl());
  EXPECT_EQ(backend->name().rfind("opencl:", 0), 0u) << backend->name();
  EXPECT_EQ(make_light_solver(*backend, LightParameters{})->name(), backend->name());
  EXPECT_EQ(roots::make_root_field_solver(*backend)->name(), backend->name());
}

TEST(ComputeBackend, AutoIsTheDefaultOpenCLDeviceOrElseTheReference) {
  const auto backend = ComputeBackend::open(DeviceChoice::parse("auto"));
  EXPECT_EQ(backend.is_opencl(), opencl_device_exists()) << backend.name();
  if (!backend.is_opencl()) EXPECT_EQ(make_light_solver(backend, LightParameters{})->name(), "reference");
}

TEST(ComputeBackend, AnOpenCLDeviceThatDoesNotExistIsAnErrorNamingIt) {
  try {
    ComputeBackend::open(DeviceChoice::parse("opencl:999"));
    FAIL() << "opened OpenCL device 999";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("999"), std::string::npos) << error.what();
    if (!opencl_backend_built)
      EXPECT_NE(std::string(error.what()).find("no OpenCL backend"), std::string::npos) << error.what();
  }
  if (!opencl_device_exists()) EXPECT_THROW(ComputeBackend::open(DeviceChoice::parse("opencl")), std::runtime_error);
}

}  // namespace
}  // namespace heliostand::compute
