#pragma once
// Device buffers kept from one use to the next (a solve of the light, a year of the root-contact field), and the
// host's writes into them without a copy. On a CPU device (PoCL) a buffer made anew is fresh memory that the
// operating system hands out page by page on its first write; on some machines that first write costs as much as the
// work done with it (docs/performance.md "The tile lists written where the device reads them"). A buffer kept and
// written again costs no such faults. Included only by opencl_*.cpp files (the OpenCL backend is optional).
#include <cstddef>
#include <limits>
#include <span>

#include <CL/opencl.hpp>

#include "compute/opencl_context.hpp"

namespace heliostand::compute {

// A device buffer kept from one use to the next, and its size.
struct KeptBuffer {
  cl::Buffer buffer;
  std::size_t bytes = 0;
  // Where pages are made resident (makes_pages_resident), how far from its start they were; for a use written in
  // parts, how far its caller made those parts resident. 0 elsewhere, and again whenever the buffer is made anew.
  std::size_t resident_bytes = 0;
};

// Whether kept_at_least makes the pages of a CPU device's buffer resident, up to the bytes asked: for a use that
// writes all of them, or not, for one that writes only parts of them (the far field's table by cell, only the cells
// a receiver reads), whose caller makes those parts resident (make_resident below) and leaves the rest unbacked.
enum class Residency { whole_use, parts_by_the_caller };

// `kept`, made anew only when `bytes` outgrow it, then with room to spare for a growing canopy or root system
// (spare_bytes; never beyond `cap_bytes` nor the device's largest buffer, unless `bytes` themselves are). What it
// held before is undefined after a regrowth. On a CPU device its first `bytes` are resident in the host's memory
// when it is returned, given Residency::whole_use, and its spare room is not.
const cl::Buffer& kept_at_least(const OpenCLContext& device, KeptBuffer& kept, std::size_t bytes,
                                std::size_t cap_bytes = std::numeric_limits<std::size_t>::max(),
                                Residency residency = Residency::whole_use);

// Bytes [first, end) of a buffer.
struct ByteRange {
  std::size_t first = 0, end = 0;
};

// Whether make_resident does anything for `device`: a CPU device's buffers are the host's memory, whose pages Linux
// can make resident (MADV_POPULATE_WRITE); a GPU's are its own.
bool makes_pages_resident(const OpenCLContext& device);

// On a CPU device, the host's pages under each of `ranges` of `buffer` made resident and writable, in one call a range
// and with one mapping of the buffer for all of them, before a kernel writes them: what kept_at_least does for a whole
// use (opencl_kept_buffer.cpp says why). Nothing on any other device, or where the system cannot.
void make_resident(const OpenCLContext& device, const cl::Buffer& buffer, std::span<const ByteRange> ranges);

// The room a kept buffer is made with beyond the `bytes` asked. On a CPU device a buffer is the host's memory, which
// the operating system backs page by page at its first write, so room never written costs address space, not memory;
// and a buffer made anew is written into fresh pages whole. So there the spare is as much again: a canopy growing year
// by year fills a buffer's new pages as it grows and is copied into a new one a few times over a run, where with an
// eighth to spare it was every eighth of its growth (docs/performance.md "Kept buffers with room to grow on a CPU
// device"). Elsewhere a buffer is the device's memory outright, and an eighth is spared.
std::size_t spare_bytes(const OpenCLContext& device, std::size_t bytes);

// Part of a buffer mapped for the host to write, its old contents given up (CL_MAP_WRITE_INVALIDATE_REGION), until
// unmap(). On a CPU device the mapping is the buffer's own memory, so what the host writes there is not copied again.
class MappedForWriting {
 public:
  MappedForWriting(const cl::CommandQueue& queue, const cl::Buffer& buffer, std::size_t bytes,
                   std::size_t offset = 0);
  MappedForWriting(const MappedForWriting&) = delete;
  MappedForWriting& operator=(const MappedForWriting&) = delete;
  ~MappedForWriting();
  void* data() const { return data_; }
  // Queued: the kernels queued after it (in order) read what was written.
  void unmap();

 private:
  cl::CommandQueue queue_;
  cl::Buffer buffer_;
  void* data_;
};

}  // namespace heliostand::compute
