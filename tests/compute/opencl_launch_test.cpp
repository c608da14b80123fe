// compute::launch: every kernel runs in work groups of one fixed size per kernel and device, whatever the number
// of items, and every item below the count runs. An automatic group size follows the item count, and PoCL compiles
// a kernel anew for every group size it meets (a compile at each of the roots' yearly queries; see
// tests/cli/kernel_compiles_cli_test.cpp for the whole program).
#include <gtest/gtest.h>

#include <vector>

#include "compute/opencl_context.hpp"
#include "compute/opencl_test_backend.hpp"

namespace heliostand::compute {
namespace {

// Each item below `count` writes the size of the group it ran in; the rest of the buffer keeps its -1.
constexpr const char* group_size_probe =
    "kernel void group_size_probe(global int* size, const int count) {\n"
    "  const int i = get_global_id(0);\n"
    "  if (i < count) size[i] = (int)get_local_size(0);\n"
    "}\n";

std::vector<int> group_sizes_seen(const OpenCLContext& device, cl::Kernel& kernel, int count) {
  const std::size_t capacity = static_cast<std::size_t>(count) + 4096;  // room for a rounded-up global size
  std::vector<int> sizes(capacity, -1);
  cl::Buffer buffer(device.context, CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR, capacity * sizeof(int), sizes.data());
  kernel.setArg(0, buffer);
  kernel.setArg(1, count);
  launch(device, kernel, static_cast<std::size_t>(count));
  device.queue.enqueueReadBuffer(buffer, CL_TRUE, 0, capacity * sizeof(int), sizes.data());
  return sizes;
}

TEST(Launch, EveryItemRunsInGroupsOfOneSizeWhateverTheCount) {
  const auto backend = opencl_backend_for_test();
  if (!backend) GTEST_SKIP() << "no OpenCL device";
  const OpenCLContext& device = *backend->opencl();
  cl::Program program = build_program(device, group_size_probe, "");
  cl::Kernel kernel(program, "group_size_probe");
  const auto size = static_cast<int>(work_group_size(kernel, device.device));
  ASSERT_GE(size, 1);
  if (device.device.getInfo<CL_DEVICE_TYPE>() & CL_DEVICE_TYPE_CPU) EXPECT_LE(size, 64) << "PoCL stack limit";
  // counts below, at and above one group, and primes an automatic size would take whole (239, 1693)
  for (const int count : {1, 63, 64, 65, 239, 1693, 4099}) {
    const std::vector<int> seen = group_sizes_seen(device, kernel, count);
    for (int i = 0; i < count; ++i)
      ASSERT_EQ(seen[i], size) << "item " << i << " of " << count << (seen[i] < 0 ? " did not run" : "");
    for (std::size_t i = count; i < seen.size(); ++i) ASSERT_EQ(seen[i], -1) << "item " << i << " of " << count;
  }
}

}  // namespace
}  // namespace heliostand::compute
