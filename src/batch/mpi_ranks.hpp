#pragma once
// The MPI layer of `heliostand batch`: when the program was started by an MPI launcher (mpirun, mpiexec,
// srun), the batch's runs are spread over its ranks; otherwise there is one rank and MPI is never touched.
// Built without MPI (no MPI found by CMake), a start under a launcher is refused, since every rank would
// otherwise run every run into the same folders.
#include <string>
#include <vector>

namespace heliostand {

class MpiRanks {
 public:
  MpiRanks();   // initialises MPI when started by a launcher
  ~MpiRanks();  // finalises it
  MpiRanks(const MpiRanks&) = delete;
  MpiRanks& operator=(const MpiRanks&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool distributed() const { return size_ > 1; }

  // Waits for every rank. No-op with one rank.
  void barrier() const;
  // Rank 0's value of `value`, on every rank.
  int broadcast_from_first(int value) const;
  // Element-wise maximum over all ranks, on every rank.
  void max_over_ranks(std::vector<int>& values) const;

 private:
  int rank_ = 0;
  int size_ = 1;
  bool initialised_ = false;
};

// True when an MPI launcher started this process (its environment variables are present).
bool started_by_mpi_launcher();

}  // namespace heliostand
