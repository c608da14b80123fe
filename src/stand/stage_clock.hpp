#pragma once
// Wall time per stage of the simulated year, for run.json.
#include <chrono>
#include <string>
#include <utility>
#include <vector>

#include "core/checkpoint_access.hpp"

namespace heliostand {

class StageClock {
 public:
  template <typename Work>
  auto time(const std::string& stage, Work work) {
    const auto start = std::chrono::steady_clock::now();
    struct Stop {
      StageClock& clock;
      const std::string& stage;
      std::chrono::steady_clock::time_point start;
      ~Stop() { clock.add(stage, std::chrono::steady_clock::now() - start); }
    } stop{*this, stage, start};
    return work();
  }
  double seconds(const std::string& stage) const {
    for (const auto& [name, value] : stages_)
      if (name == stage) return value;
    return 0;
  }
  const std::vector<std::pair<std::string, double>>& stages() const { return stages_; }

 private:
  friend struct checkpoint::Access;
  void add(const std::string& stage, std::chrono::steady_clock::duration elapsed) {
    const double seconds = std::chrono::duration<double>(elapsed).count();
    for (auto& [name, value] : stages_)
      if (name == stage) {
        value += seconds;
        return;
      }
    stages_.emplace_back(stage, seconds);
  }
  std::vector<std::pair<std::string, double>> stages_;
};

}  // namespace heliostand
