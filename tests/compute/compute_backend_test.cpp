// One compute backend per run: chosen once from --device, and both solver factories (light and roots) put
// their solver on it.
#include "compute/compute_backend.hpp"

#include <gtest/gtest.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "compute/opencl_test_backend.hpp"
#ifdef HELIOSTAND_HAVE_OPENCL
#include "compute/opencl_context.hpp"
#endif
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

// A machine may carry PoCL and a GPU's driver, enumerated in either order: the default is the first GPU.
TEST(ComputeBackend, TheDefaultDeviceIsTheFirstGPUElseTheFirstDevice) {
  using Types = std::vector<std::string>;
  EXPECT_EQ(default_opencl_device(Types{"CPU", "GPU"}), 1);
  EXPECT_EQ(default_opencl_device(Types{"GPU", "CPU"}), 0);
  EXPECT_EQ(default_opencl_device(Types{"CPU", "accelerator", "GPU", "GPU"}), 2);
  EXPECT_EQ(default_opencl_device(Types{"CPU", "CPU"}), 0);
  EXPECT_EQ(default_opencl_device(Types{"accelerator"}), 0);
  EXPECT_EQ(default_opencl_device(Types{}), std::nullopt);
}

// `heliostand devices` marks the device that `auto` and `opencl` then open, and only that one.
TEST(ComputeBackend, AutoOpensTheDeviceTheListMarksAsDefault) {
  const auto devices = list_opencl_devices();
  if (devices.empty()) GTEST_SKIP() << "no OpenCL device";
  std::vector<std::string> types;
  int marked = -1, marks = 0;
  for (const auto& device : devices) {
    types.push_back(device.type);
    if (device.is_default) marked = device.index, ++marks;
  }
  EXPECT_EQ(marks, 1);
  EXPECT_EQ(std::optional<int>(marked), default_opencl_device(types));
#ifdef HELIOSTAND_HAVE_OPENCL
  for (const char* choice : {"auto", "opencl"}) {
    const auto backend = ComputeBackend::open(DeviceChoice::parse(choice));
    ASSERT_TRUE(backend.is_opencl()) << choice;
    EXPECT_EQ(backend.opencl()->index, marked) << choice;
  }
#endif
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
