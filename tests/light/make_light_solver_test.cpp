#include "light/make_light_solver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "compute/compute_backend.hpp"
#include "light/sky_openness.hpp"

namespace heliostand {
namespace {

using compute::ComputeBackend;
using compute::DeviceChoice;

ComputeBackend backend(const char* device) { return ComputeBackend::open(DeviceChoice::parse(device)); }

TEST(DeviceChoice, ParsesTheDeviceStrings) {
  EXPECT_EQ(DeviceChoice::parse("auto").kind, DeviceChoice::Kind::automatic);
  EXPECT_EQ(DeviceChoice::parse("reference").kind, DeviceChoice::Kind::reference);
  EXPECT_EQ(DeviceChoice::parse("opencl").kind, DeviceChoice::Kind::opencl);
  EXPECT_FALSE(DeviceChoice::parse("opencl").opencl_index.has_value());
  EXPECT_EQ(DeviceChoice::parse("opencl:2").opencl_index, 2);
  for (const char* bad : {"cuda", "opencl:", "opencl:-1", "opencl:x", "opencl:1x", "Reference"})
    EXPECT_THROW(DeviceChoice::parse(bad), std::invalid_argument) << bad;
}

// Which solver each backend gets, and a missing device: tests/compute/compute_backend_test.cpp.

TEST(MakeLightSolver, BadParametersAreRejectedWithTheFieldName) {
  LightParameters p;
  p.transmittance = 1.5;
  try {
    make_light_solver(ComputeBackend::reference(), p);
    FAIL() << "accepted t = 1.5";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("transmittance"), std::string::npos) << e.what();
  }
  p = {};
  p.periodic = true;  // without plot bounds
  EXPECT_THROW(make_light_solver(ComputeBackend::reference(), p), std::invalid_argument);
}

TEST(MakeLightSolver, ReceiverOutsideTheStandIsAnError) {
  const std::vector<LeafBall> balls{{{0, 0, 0}, 0.5}, {{0, 0, 2}, 0.5}};
  const std::vector<std::uint32_t> receivers{1, 2};
  for (const char* device : {"reference", "auto"})
    EXPECT_THROW(make_light_solver(backend(device), LightParameters{})->solve_for(balls, receivers), std::out_of_range)
        << device;
}

TEST(SkyOpenness, IsTheMeanLightOfEachTreesBalls) {
  std::vector<LightSample> samples(5);
  const double light[] = {0.2, 0.4, 0.9, 1.0, 0.6};
  for (int k = 0; k < 5; ++k) samples[k].light = light[k];
  const std::vector<int> tree{0, 0, 2, 2, 2};
  const auto openness = sky_openness(samples, tree, 3);
  ASSERT_EQ(openness.size(), 3u);
  EXPECT_DOUBLE_EQ(openness[0], 0.3);
  EXPECT_TRUE(std::isnan(openness[1]));  // no foliage, no view of the sky
  EXPECT_NEAR(openness[2], 2.5 / 3, 1e-15);
  EXPECT_THROW(sky_openness(samples, std::vector<int>{0, 0, 3, 0, 0}, 3), std::invalid_argument);
}

}  // namespace
}  // namespace heliostand
