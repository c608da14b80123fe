#include "stand/progress.hpp"

#include <fmt/core.h>

#include <cstdio>
#include <string>

#include "core/seconds_since.hpp"

namespace heliostand {

ProgressLine::ProgressLine(int total_years, bool enabled)
    : total_(total_years), enabled_(enabled && total_years > 0), start_(std::chrono::steady_clock::now()) {}

void ProgressLine::update(int years_done) {
  if (!enabled_) return;
  constexpr int width = 30;
  const double fraction = static_cast<double>(years_done) / total_;
  const int filled = static_cast<int>(fraction * width);
  const double elapsed = seconds_since(start_);
  const double remaining = years_done > 0 ? elapsed * (total_ - years_done) / years_done : 0.0;
  const int minutes = static_cast<int>(remaining) / 60, seconds = static_cast<int>(remaining) % 60;
  fmt::print(stderr, "\ryear {}/{} [{}{}] {:3.0f}%  ETA {}m {:02d}s ", years_done, total_,
             std::string(filled, '='), std::string(width - filled, ' '), 100 * fraction, minutes, seconds);
  std::fflush(stderr);
}

void ProgressLine::finish() {
  if (enabled_) fmt::print(stderr, "\n");
}

}  // namespace heliostand
