// compute::kept_at_least: a buffer kept from one use to the next is made anew only when a use outgrows it, and then
// with room to spare: as much again on a CPU device, whose untouched room costs address space and not memory, an
// eighth elsewhere; never beyond the caller's cap nor the device's largest buffer, unless the use itself is. On a CPU
// device the part in use is resident in the host's memory when it is returned, and the spare room is not; a caller
// that writes only parts of a buffer makes just those resident (compute::make_resident).
#include <gtest/gtest.h>

#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <vector>

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

// The host's whole pages within [from, to) of a CPU device's buffer, mapped without a copy, and how many of them are
// resident (mincore).
struct Pages {
  std::size_t whole = 0, resident = 0;
};

Pages pages_of(const OpenCLContext& device, const cl::Buffer& buffer, std::size_t from, std::size_t to) {
  void* mapped = device.queue.enqueueMapBuffer(buffer, CL_TRUE, CL_MAP_READ, from, to - from);
  const auto page = std::uintptr_t(sysconf(_SC_PAGESIZE));
  const auto begin = (reinterpret_cast<std::uintptr_t>(mapped) + page - 1) & ~(page - 1);  // whole pages only
  const auto end = (reinterpret_cast<std::uintptr_t>(mapped) + (to - from)) & ~(page - 1);
  std::vector<unsigned char> in_core((end - begin) / page);
  const int status = mincore(reinterpret_cast<void*>(begin), end - begin, in_core.data());
  device.queue.enqueueUnmapMemObject(buffer, mapped);
  device.queue.finish();
  EXPECT_EQ(status, 0) << "mincore failed";
  Pages pages{in_core.size(), 0};
  for (const unsigned char flags : in_core) pages.resident += flags & 1u;
  return pages;
}

TEST(KeptBuffer, OnACpuDeviceItsPartInUseIsResidentAndItsSpareRoomNot) {
  const auto backend = opencl_backend_for_test();
  if (!backend) GTEST_SKIP() << "no OpenCL device";
  const OpenCLContext& device = *backend->opencl();
  constexpr std::size_t mib = std::size_t(1) << 20;
  KeptBuffer kept;
  kept_at_least(device, kept, 64 * mib);
  if (!(device.type & CL_DEVICE_TYPE_CPU)) {  // a GPU's buffer is its own memory, made resident by its driver
    EXPECT_EQ(kept.resident_bytes, 0u);
    return;
  }
  ASSERT_EQ(kept.bytes, 128 * mib);
  // Fresh memory (glibc maps a block this large anew), none of it written: what is resident, the call made so.
  // The spare is looked at 8 MiB clear of the part in use and 2 MiB clear of the end, so that huge pages (where the
  // kernel makes every mapping of them) cannot reach it from either side.
  const Pages in_use = pages_of(device, kept.buffer, 0, 64 * mib);
  const Pages spare = pages_of(device, kept.buffer, 72 * mib, 126 * mib);
  EXPECT_GT(in_use.whole, 0u);
  EXPECT_EQ(in_use.resident, in_use.whole);
  EXPECT_GT(spare.whole, 0u);
  EXPECT_EQ(spare.resident, 0u);
  // a use grown within the room: the buffer kept, its new part resident too, the rest of the room not
  const cl_mem first = kept.buffer();
  EXPECT_EQ(kept_at_least(device, kept, 96 * mib)(), first);
  const Pages grown = pages_of(device, kept.buffer, 0, 96 * mib);
  const Pages rest = pages_of(device, kept.buffer, 104 * mib, 126 * mib);
  EXPECT_EQ(grown.resident, grown.whole);
  EXPECT_EQ(rest.resident, 0u);
}

TEST(KeptBuffer, AUseWrittenInPartsHasJustThosePartsMadeResident) {
  const auto backend = opencl_backend_for_test();
  if (!backend) GTEST_SKIP() << "no OpenCL device";
  const OpenCLContext& device = *backend->opencl();
  constexpr std::size_t mib = std::size_t(1) << 20;
  KeptBuffer kept;
  kept_at_least(device, kept, 64 * mib, 64 * mib, Residency::parts_by_the_caller);  // no room: at the cap
  const ByteRange parts[] = {{8 * mib, 16 * mib}, {32 * mib + 100, 40 * mib - 100}};
  make_resident(device, kept.buffer, parts);
  EXPECT_EQ(kept.resident_bytes, 0u);
  if (!(device.type & CL_DEVICE_TYPE_CPU)) return;  // a GPU's buffer is its own memory, made resident by its driver
  // Fresh memory, none of it written. A range's first and last pages may be shared with what lies beside it, so the
  // parts are looked at within their whole pages and the rest 2 MiB clear of them (huge pages: see the test above).
  for (const ByteRange part : parts) {
    const Pages pages = pages_of(device, kept.buffer, part.first, part.end);
    EXPECT_GT(pages.whole, 0u);
    EXPECT_EQ(pages.resident, pages.whole) << "part from " << part.first;
  }
  for (const ByteRange gap : {ByteRange{0, 6 * mib}, ByteRange{18 * mib, 30 * mib}, ByteRange{42 * mib, 64 * mib}}) {
    const Pages pages = pages_of(device, kept.buffer, gap.first, gap.end);
    EXPECT_GT(pages.whole, 0u);
    EXPECT_EQ(pages.resident, 0u) << "gap from " << gap.first;
  }
}

}  // namespace
}  // namespace heliostand::compute
