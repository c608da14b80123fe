#pragma once
// Wall time per stage of the simulated year, for run.json, and the process's CPU time in each stage, for `bench
// stand`: CPU over wall is how many cores a stage kept busy, which tells a serial stage (a core idle on a 2-core
// machine) from one that waits on nothing (docs/performance.md).
#include <chrono>
#include <ctime>
#include <string>
#include <utility>
#include <vector>

#include "core/checkpoint_access.hpp"
#include "core/seconds_since.hpp"

namespace heliostand {

// CPU seconds the whole process (every thread: the worker threads and an OpenCL CPU device's) has used so far.
inline double process_cpu_seconds() {
  timespec now{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

class StageClock {
 public:
  using Seconds = std::vector<std::pair<std::string, double>>;

  template <typename Work>
  auto time(const std::string& stage, Work work) {
    struct Stop {
      StageClock& clock;
      const std::string& stage;
      std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
      double cpu_start = process_cpu_seconds();
      ~Stop() {
        add(clock.stages_, stage, seconds_since(start));
        add(clock.cpu_, stage, process_cpu_seconds() - cpu_start);
      }
    } stop{*this, stage};
    return work();
  }
  double seconds(const std::string& stage) const { return find(stages_, stage); }
  double cpu_seconds(const std::string& stage) const { return find(cpu_, stage); }
  const Seconds& stages() const { return stages_; }
  // The CPU seconds of each stage. Not kept in checkpoints: a resumed run's are those of its own session (`bench
  // stand`, their reader, does not resume).
  const Seconds& cpu_stages() const { return cpu_; }

 private:
  friend struct checkpoint::Access;
  static double find(const Seconds& totals, const std::string& stage) {
    for (const auto& [name, value] : totals)
      if (name == stage) return value;
    return 0;
  }
  static void add(Seconds& totals, const std::string& stage, double seconds) {
    for (auto& [name, value] : totals)
      if (name == stage) {
        value += seconds;
        return;
      }
    totals.emplace_back(stage, seconds);
  }
  Seconds stages_;
  Seconds cpu_;
};

}  // namespace heliostand
