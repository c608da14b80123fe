#include "light/light_solver.hpp"

#include <numeric>

namespace heliostand {

std::vector<LightSample> LightSolver::solve(std::span<const LeafBall> balls) {
  std::vector<std::uint32_t> everyone(balls.size());
  std::iota(everyone.begin(), everyone.end(), 0u);
  return solve_for(balls, everyone);
}

}  // namespace heliostand
