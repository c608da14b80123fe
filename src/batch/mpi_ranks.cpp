#include "batch/mpi_ranks.hpp"

#include <cstdlib>
#include <stdexcept>

#ifdef HELIOSTAND_HAVE_MPI
#include <mpi.h>
#endif

namespace heliostand {

bool started_by_mpi_launcher() {
  // Open MPI's mpirun, PMIx (Open MPI 4+, srun --mpi=pmix), PMI-1/2 (srun --mpi=pmi2, MPICH's Hydra).
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"}) {
    if (std::getenv(variable) != nullptr) return true;
  }
  return false;
}

#ifdef HELIOSTAND_HAVE_MPI

MpiRanks::MpiRanks() {
  if (!started_by_mpi_launcher()) return;
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);  // only the main thread calls MPI
  initialised_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiRanks::~MpiRanks() {
  if (initialised_) MPI_Finalize();
}

void MpiRanks::barrier() const {
  if (initialised_) MPI_Barrier(MPI_COMM_WORLD);
}

int MpiRanks::broadcast_from_first(int value) const {
  if (initialised_) MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return value;
}

void MpiRanks::max_over_ranks(std::vector<int>& values) const {
  if (!initialised_ || values.empty()) return;
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_INT, MPI_MAX, MPI_COMM_WORLD);
}

#else

MpiRanks::MpiRanks() {
  if (started_by_mpi_launcher()) {
    throw std::runtime_error(
        "started by an MPI launcher, but this heliostand was built without MPI (install libopenmpi-dev and "
        "rebuild); run `heliostand batch` without mpirun/srun to use the local worker pool");
  }
}
MpiRanks::~MpiRanks() = default;
void MpiRanks::barrier() const {}
int MpiRanks::broadcast_from_first(int value) const { return value; }
void MpiRanks::max_over_ranks(std::vector<int>&) const {}

#endif

}  // namespace heliostand
