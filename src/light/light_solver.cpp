#include "light/light_solver.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

namespace heliostand {

std::vector<LightSample> LightSolver::solve(std::span<const LeafBall> balls) {
  std::vector<std::uint32_t> everyone(balls.size());
  std::iota(everyone.begin(), everyone.end(), 0u);
  return solve_for(balls, everyone);
}

std::vector<LightSample> LightSolver::solve_each_alone(std::span<const LeafBall> balls,
                                                       std::span<const std::size_t> group_start) {
  check_groups(balls, group_start);
  std::vector<LightSample> samples;
  samples.reserve(balls.size());
  for (std::size_t g = 0; g + 1 < group_start.size(); ++g) {
    const auto group = solve(balls.subspan(group_start[g], group_start[g + 1] - group_start[g]));
    samples.insert(samples.end(), group.begin(), group.end());
  }
  return samples;
}

std::optional<LightSolver::StandAndAlone> LightSolver::solve_with_each_alone(std::span<const LeafBall>,
                                                                            std::span<const std::size_t>,
                                                                            const LightSolver&) {
  return std::nullopt;
}

void LightSolver::check_groups(std::span<const LeafBall> balls, std::span<const std::size_t> group_start) {
  const bool rising = std::is_sorted(group_start.begin(), group_start.end());
  if (group_start.empty() || group_start.front() != 0 || group_start.back() != balls.size() || !rising)
    throw std::invalid_argument("light solver: group starts must rise from 0 to the " +
                                std::to_string(balls.size()) + " leaf balls");
}

void LightSolver::check_receivers(std::span<const LeafBall> balls, std::span<const std::uint32_t> receivers) {
  for (auto r : receivers)
    if (r >= balls.size())
      throw std::out_of_range("light solver: receiver " + std::to_string(r) + " is not one of the " +
                              std::to_string(balls.size()) + " leaf balls");
}

}  // namespace heliostand
