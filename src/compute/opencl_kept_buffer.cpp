#include "compute/opencl_kept_buffer.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>

#include <sys/mman.h>
#include <unistd.h>

namespace heliostand::compute {

std::size_t spare_bytes(const OpenCLContext& device, std::size_t bytes) {
  return (device.type & CL_DEVICE_TYPE_CPU) ? bytes : bytes / 8;
}

const cl::Buffer& kept_at_least(const OpenCLContext& device, KeptBuffer& kept, std::size_t bytes,
                                std::size_t cap_bytes, Residency residency) {
  if (bytes > kept.bytes) {
    kept.buffer = cl::Buffer();  // let the old one go before the new one is made
    std::size_t most = cap_bytes;
    if (device.memory.buffer_bytes > 0) most = std::min<std::uint64_t>(most, device.memory.buffer_bytes);
    const std::size_t room = bytes > most ? 0 : std::min(spare_bytes(device, bytes), most - bytes);
    kept.bytes = bytes + room;
    kept.buffer = cl::Buffer(device.context, CL_MEM_READ_WRITE, kept.bytes);
    kept.resident_bytes = 0;
  }
  if (residency == Residency::whole_use && makes_pages_resident(device) && bytes > kept.resident_bytes) {
    const ByteRange fresh{kept.resident_bytes, bytes};
    make_resident(device, kept.buffer, {&fresh, 1});
    kept.resident_bytes = bytes;
  }
  return kept.buffer;
}

bool makes_pages_resident(const OpenCLContext& device) {
#ifdef MADV_POPULATE_WRITE
  return (device.type & CL_DEVICE_TYPE_CPU) != 0;
#else
  return false;
#endif
}

// On the 2-core virtual machines of docs/performance.md a fresh 4 KiB page's first write costs far more than its bytes,
// 2.7 s a GiB; made resident first by Linux's MADV_POPULATE_WRITE (5.14), the call costs 0.13 s a GiB and the first
// write 1.25 (validation/bench/first_touch.py), which took a first light solve to 0.68-0.87 of its time
// (docs/performance.md "Kept buffers' pages made resident in one call"). The advice keeps what the pages hold; where
// it is unknown or fails, the kernels' writes fault the pages in as before. Only the ranges given: a buffer's spare
// room stays address space.
void make_resident(const OpenCLContext& device, const cl::Buffer& buffer, std::span<const ByteRange> ranges) {
#ifdef MADV_POPULATE_WRITE
  if (!makes_pages_resident(device) || ranges.empty()) return;
  std::size_t first = ranges.front().first, end = ranges.front().end;
  for (const ByteRange& range : ranges) first = std::min(first, range.first), end = std::max(end, range.end);
  if (end <= first) return;
  // Mapped, a CPU device's buffer is its own memory: no copy, and CL_MAP_WRITE keeps what it holds, as the advice does.
  auto* mapped = static_cast<char*>(device.queue.enqueueMapBuffer(buffer, CL_TRUE, CL_MAP_WRITE, first, end - first));
  const auto page = std::uintptr_t(sysconf(_SC_PAGESIZE));
  for (const ByteRange& range : ranges) {
    if (range.end <= range.first) continue;
    const auto begin = reinterpret_cast<std::uintptr_t>(mapped + (range.first - first)) & ~(page - 1);
    const auto stop = reinterpret_cast<std::uintptr_t>(mapped + (range.end - first));
    madvise(reinterpret_cast<void*>(begin), stop - begin, MADV_POPULATE_WRITE);
  }
  device.queue.enqueueUnmapMemObject(buffer, mapped);
#else
  (void)device, (void)buffer, (void)ranges;
#endif
}

MappedForWriting::MappedForWriting(const cl::CommandQueue& queue, const cl::Buffer& buffer, std::size_t bytes,
                                   std::size_t offset)
    : queue_(queue), buffer_(buffer),
      data_(queue_.enqueueMapBuffer(buffer_, CL_TRUE, CL_MAP_WRITE_INVALIDATE_REGION, offset, bytes)) {}

MappedForWriting::~MappedForWriting() {
  try {
    unmap();
  } catch (...) {  // only on an exception's way out, which goes on; unmap() called in time reports its own errors
  }
}

void MappedForWriting::unmap() {
  if (data_ != nullptr) queue_.enqueueUnmapMemObject(buffer_, std::exchange(data_, nullptr));
}

}  // namespace heliostand::compute
