#include "compute/opencl_kept_buffer.hpp"

#include <algorithm>
#include <utility>

namespace heliostand::compute {

const cl::Buffer& kept_at_least(const cl::Context& context, KeptBuffer& kept, std::size_t bytes,
                                std::size_t cap_bytes) {
  if (bytes > kept.bytes) {
    kept.buffer = cl::Buffer();  // let the old one go before the new one is made
    kept.bytes = std::max(bytes, std::min(bytes + bytes / 8, cap_bytes));
    kept.buffer = cl::Buffer(context, CL_MEM_READ_WRITE, kept.bytes);
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
