#include "compute/opencl_kept_buffer.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>

namespace heliostand::compute {

std::size_t spare_bytes(const OpenCLContext& device, std::size_t bytes) {
  return (device.type & CL_DEVICE_TYPE_CPU) ? bytes : bytes / 8;
}

const cl::Buffer& kept_at_least(const OpenCLContext& device, KeptBuffer& kept, std::size_t bytes,
                                std::size_t cap_bytes) {
  if (bytes > kept.bytes) {
    kept.buffer = cl::Buffer();  // let the old one go before the new one is made
    std::size_t most = cap_bytes;
    if (device.memory.buffer_bytes > 0) most = std::min<std::uint64_t>(most, device.memory.buffer_bytes);
    const std::size_t room = bytes > most ? 0 : std::min(spare_bytes(device, bytes), most - bytes);
    kept.bytes = bytes + room;
    kept.buffer = cl::Buffer(device.context, CL_MEM_READ_WRITE, kept.bytes);
  }
  return kept.buffer;
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
