#include "coupling/crown_root_balance.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/compass_sector.hpp"

namespace heliostand {

int crown_path_of_shoot(const ConiferTree& tree, int shoot_index) {
  const auto& axes = tree.axes();
  const int axis = tree.shoots().at(static_cast<std::size_t>(shoot_index)).axis;
  const int first_order = axes.at(static_cast<std::size_t>(axis)).first_order_root;
  if (first_order < 0) return -1;  // the trunk (leader)
  return compass_sector(axes[static_cast<std::size_t>(first_order)].azimuth_rad);
}

PathValues light_by_path(const ConiferTree& tree, std::span<const LightSample> light, double sky_scale) {
  PathValues sum{};
  const std::vector<int> shoots = tree.foliage_shoot_indices();
  const std::size_t n = std::min(shoots.size(), light.size());
  for (std::size_t i = 0; i < n; ++i) {
    const double received = light[i].light * sky_scale;
    const int path = crown_path_of_shoot(tree, shoots[i]);
    if (path >= 0) {
      sum[static_cast<std::size_t>(path)] += received;
    } else {
      for (double& s : sum) s += received / crown_path_count;
    }
  }
  return sum;
}

double branch_bonus(double lp, double wp, double alpha_b) {
  if (lp <= 0.0 && wp <= 0.0) return 0.0;
  const double ratio = lp <= 0.0 ? 2.0 : std::min(wp / lp, 2.0);
  return alpha_b * (ratio - 1.0);
}

double root_bonus(double lp, double wp, double alpha_r) {
  if (lp <= 0.0 && wp <= 0.0) return 0.0;
  const double ratio = wp <= 0.0 ? 2.0 : std::min(lp / wp, 2.0);
  return alpha_r * (ratio - 1.0);
}

PathBalance balance_paths(const PathValues& light_sum, const PathValues& uptake_sum, const CouplingParameters& p) {
  PathBalance balance;
  for (std::size_t n = 0; n < crown_path_count; ++n) {
    balance.lp[n] = p.rho * light_sum[n];
    balance.wp[n] = p.tau * uptake_sum[n];
    balance.branch[n] = branch_bonus(balance.lp[n], balance.wp[n], p.alpha_b);
    balance.root[n] = root_bonus(balance.lp[n], balance.wp[n], p.alpha_r);
  }
  return balance;
}

}  // namespace heliostand
