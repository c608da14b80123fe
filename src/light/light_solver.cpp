#include "light/light_solver.hpp"

#include <numeric>
#include <stdexcept>
#include <string>

namespace heliostand {

std::vector<LightSample> LightSolver::solve(std::span<const LeafBall> balls) {
  std::vector<std::uint32_t> everyone(balls.size());
  std::iota(everyone.begin(), everyone.end(), 0u);
  return solve_for(balls, everyone);
}

void LightSolver::check_receivers(std::span<const LeafBall> balls, std::span<const std::uint32_t> receivers) {
  for (auto r : receivers)
    if (r >= balls.size())
      throw std::out_of_range("light solver: receiver " + std::to_string(r) + " is not one of the " +
                              std::to_string(balls.size()) + " leaf balls");
}

}  // namespace heliostand
