#pragma once
// Runs jobs on a fixed number of worker threads, each job a blocking call (here: one child process), and
// reports progress with an estimated time to finish.
#include <cstddef>
#include <functional>
#include <string>

namespace heliostand {

struct JobReport {
  std::string name;
  bool ok = true;
  std::string note;  // why it failed, or "finished earlier"
};

// Calls `job(i)` for every i in [0, count) on `workers` threads (at least 1) and returns when all are done.
// After each job a line "[done/count] NAME ok|FAILED ...; ETA ..." goes to stderr, prefixed by `label`
// (the MPI rank, or empty). A job that throws is reported as failed; the others go on.
void run_worker_pool(std::size_t count, unsigned workers, const std::string& label,
                     const std::function<JobReport(std::size_t)>& job);

// "1 h 02 min", "3 min 05 s", "12 s": a duration for people.
std::string human_duration(double seconds);

}  // namespace heliostand
