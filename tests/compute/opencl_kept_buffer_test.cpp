// compute::kept_at_least: a buffer kept from one use to the next is made anew only when a use outgrows it, and then
// with room to spare: as much again on a CPU device, whose untouched room costs address space and not memory, an
// eighth elsewhere; never beyond the caller's cap nor the device's largest buffer, unless the use itself is.
#include <gtest/gtest.h>

#include <cstddef>

#include "compute/opencl_context.hpp"
#include "compute/opencl_kept_buffer.hpp"
#include "compute/opencl_test_backend.hpp"

namespace heliostand::compute {
namespace {

TEST(KeptBuffer, SparesAsMuchAgainOnACpuDeviceAndAnEighthOnAnyOther) {
  OpenCLContext cpu, gpu, accelerator;
  cpu.type = CL_DEVICE_TYPE_CPU;
  gpu.type = CL_DEVICE_TYPE_GPU;
  accelerator.type = CL_DEVICE_TYPE_ACCELERATOR;
  EXPECT_EQ(spare_bytes(cpu, 8000), 8000u);
  EXPECT_EQ(spare_bytes(gpu, 8000), 1000u);
  EXPECT_EQ(spare_bytes(accelerator, 8000), 1000u);
}

TEST(KeptBuffer, IsMadeAnewOnlyWhenOutgrownAndThenWithItsSpare) {
  const auto backend = opencl_backend_for_test();
  if (!backend) GTEST_SKIP() << "no OpenCL device";
  const OpenCLContext& device = *backend->opencl();
  KeptBuffer kept;
  const cl_mem first = kept_at_least(device, kept, 4096)();
  EXPECT_EQ(kept.bytes, 4096 + spare_bytes(device, 4096));
  EXPECT_EQ(kept.buffer.getInfo<CL_MEM_SIZE>(), kept.bytes);
  // a use within the room keeps the buffer, a smaller one too
  EXPECT_EQ(kept_at_least(device, kept, kept.bytes)(), first);
  EXPECT_EQ(kept_at_least(device, kept, 16)(), first);
  // one byte past it: made anew, with the spare of the new use
  const std::size_t outgrown = kept.bytes + 1;
  kept_at_least(device, kept, outgrown);
  EXPECT_EQ(kept.bytes, outgrown + spare_bytes(device, outgrown));
  EXPECT_EQ(kept.buffer.getInfo<CL_MEM_SIZE>(), kept.bytes);
}

TEST(KeptBuffer, SparesNothingBeyondTheCapOrTheDevicesLargestBuffer) {
  const auto backend = opencl_backend_for_test();
  if (!backend) GTEST_SKIP() << "no OpenCL device";
  const OpenCLContext& device = *backend->opencl();
  KeptBuffer capped;
  kept_at_least(device, capped, 4000, 4100);  // a spare of at least 500 bytes, cut at the cap
  EXPECT_EQ(capped.bytes, 4100u);
  KeptBuffer over_the_cap;
  kept_at_least(device, over_the_cap, 5000, 4100);  // the use itself beyond the cap: exactly the use
  EXPECT_EQ(over_the_cap.bytes, 5000u);
  OpenCLContext small_device = device;  // a device whose largest buffer is 4 200 bytes
  small_device.memory.buffer_bytes = 4200;
  KeptBuffer on_small;
  kept_at_least(small_device, on_small, 4000);
  EXPECT_EQ(on_small.bytes, 4200u);
}

}  // namespace
}  // namespace heliostand::compute
