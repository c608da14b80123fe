#include "batch/worker_pool.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>

#include "core/parallel_for.hpp"
#include "core/seconds_since.hpp"

namespace heliostand {

std::string human_duration(double seconds) {
  const long total = std::lround(std::max(0.0, seconds));
  if (total >= 3600) return fmt::format("{} h {:02} min", total / 3600, (total % 3600) / 60);
  if (total >= 60) return fmt::format("{} min {:02} s", total / 60, total % 60);
  return fmt::format("{} s", total);
}

namespace {

// Progress for people: done/count, and an ETA from the pace so far (runs of one batch are alike, so the pace of
// the first few is a fair guess for the rest).
class Progress {
 public:
  Progress(std::size_t count, std::string label)
      : count_(count), label_(std::move(label)), start_(std::chrono::steady_clock::now()) {}

  void finished(const JobReport& report) {
    const std::lock_guard lock(mutex_);
    ++done_;
    const double elapsed = seconds_since(start_);
    const std::size_t left = count_ - done_;
    // elapsed / done is the wall time per job at this pool's pace (all workers together).
    const double eta = elapsed / static_cast<double>(done_) * static_cast<double>(left);
    const std::string eta_text = left == 0 ? "done" : "ETA " + human_duration(eta);
    fmt::print(stderr, "{}[{}/{}] {} {}{}{}; {} elapsed, {}\n", label_, done_, count_, report.name,
               report.ok ? "ok" : "FAILED", report.note.empty() ? "" : ": ", report.note, human_duration(elapsed),
               eta_text);
    std::fflush(stderr);
  }

 private:
  std::mutex mutex_;
  std::size_t count_, done_ = 0;
  std::string label_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace

void run_worker_pool(std::size_t count, unsigned workers, const std::string& label,
                     const std::function<JobReport(std::size_t)>& job) {
  Progress progress(count, label);
  std::atomic<std::size_t> next{0};
  const auto work = [&] {
    for (std::size_t i = next++; i < count; i = next++) {
      JobReport report;
      try {
        report = job(i);
      } catch (const std::exception& e) {
        report = {fmt::format("job {}", i), false, e.what()};
      }
      progress.finished(report);
    }
  };
  run_on_threads(std::max<std::size_t>(1, std::min<std::size_t>(workers, count)), work);
}

}  // namespace heliostand
