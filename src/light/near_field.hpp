#pragma once
// Candidate culling: a k-d tree (FLANN KDTreeSingleIndex, deterministic) over occluder centres, rebuilt
// every solve; a radius search gives each receiver the occluders whose centre lies within the cut-off.
// The result is CSR arrays (start offsets + occluder indices), the layout the OpenCL kernel reads.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "light/occluders.hpp"

namespace heliostand {

struct CandidateLists {
  std::vector<std::uint32_t> start;     // receiver slot r has occluders[start[r] .. start[r+1])
  std::vector<std::uint32_t> occluders; // indices into the OccluderSet (never the receiver itself)
};

class NearFieldSearch {
 public:
  NearFieldSearch(const OccluderSet& occluders, double cutoff_m);
  ~NearFieldSearch();
  NearFieldSearch(const NearFieldSearch&) = delete;
  NearFieldSearch& operator=(const NearFieldSearch&) = delete;

  // Near-field occluders of each receiver (receivers index the stand's balls, i.e. the first
  // ball_count entries of the OccluderSet).
  CandidateLists candidates(std::span<const std::uint32_t> receivers) const;

 private:
  struct Index;
  const OccluderSet& occluders_;
  double cutoff_m_;
  std::vector<double> coordinates_;  // row-major n x 3, owned here because FLANN keeps a pointer
  std::unique_ptr<Index> index_;
};

}  // namespace heliostand
