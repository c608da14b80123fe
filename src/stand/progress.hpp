#pragma once
// "year 12/30 [=====>      ] 40%  ETA 1m 20s" on stderr, redrawn in place; only on a terminal.
#include <chrono>

namespace heliostand {

class ProgressLine {
 public:
  ProgressLine(int total_years, bool enabled);
  void update(int years_done);
  void finish();

 private:
  int total_;
  bool enabled_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace heliostand
