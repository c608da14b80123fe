#pragma once
// heliostand batch: every run of a manifest, each in its own process and output folder, on a local worker
// pool, or spread over MPI ranks when started by mpirun/srun (each rank then runs its share on its own pool).
#include <filesystem>
#include <optional>
#include <string>

namespace heliostand {

struct BatchOptions {
  std::filesystem::path manifest;
  std::optional<std::filesystem::path> out;  // overrides the manifest's `out`
  unsigned jobs = 0;                         // runs at once per rank; 0: the cores (1 per rank under MPI)
  bool force = false;                        // delete an earlier batch in the root and start over
  bool no_vtk = false;                       // tables only (overrides the manifest's `vtk = true`)
  std::optional<std::string> device;         // overrides the manifest's and the scenarios' device
  int checkpoint_every = 0;                  // years between each run's checkpoints; a restarted batch resumes from them
};

// Returns the exit status: 0 every run finished, 1 a run failed (the others still ran), 2 bad manifest or
// output folder (nothing was run). Throws InputError / OutputFolderError for bad input (cli/report_errors).
int run_batch(const BatchOptions& options);

}  // namespace heliostand
