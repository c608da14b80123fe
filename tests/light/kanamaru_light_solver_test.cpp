#include "light/kanamaru_light_solver.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "address_space_limit.hpp"

namespace heliostand {
namespace {

// Forty leaf balls in two layers of a 4 m square, close enough to shade one another and some to enclose a
// neighbour's centre (where the two rules differ).
std::vector<LeafBall> two_layers() {
  std::vector<LeafBall> balls;
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 5; ++x) balls.push_back({{0.8 * x + 0.1 * z, 0.9 * y, 1.0 + 0.7 * z}, 0.5});
  return balls;
}

bool same_light(const std::vector<LightSample>& a, const std::vector<LightSample>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (a[k].light != b[k].light || a[k].vector != b[k].vector) return false;
  return true;
}

// Where the process may start no more threads (its limit of threads, as on a shared cluster), the calling thread
// lights every ball, under both rules, as the solver's threads do. Before, the thread that failed to start threw
// std::system_error out of the solve (and where another had started before it, the program ended: a std::thread
// destroyed unjoined).
TEST(KanamaruLightSolver, WhereNoThreadCanStartTheCallerLightsEveryBall) {
  const std::vector<LeafBall> balls = two_layers();
  const LightParameters parameters;
  const std::vector<LightSample> seed_rule = KanamaruLightSolver(parameters, false).solve(balls);
  const std::vector<LightSample> stand_rule = KanamaruLightSolver(parameters, true).solve(balls);
  ASSERT_FALSE(same_light(seed_rule, stand_rule)) << "the two rules should differ on these balls";
  testing::expect_where_no_thread_can_start([&] {
    return same_light(KanamaruLightSolver(parameters, false).solve(balls), seed_rule) &&
           same_light(KanamaruLightSolver(parameters, true).solve(balls), stand_rule);
  });
}

}  // namespace
}  // namespace heliostand
