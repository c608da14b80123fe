#include "architecture/crown_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

namespace heliostand {

namespace {

double quadrat_cv(const std::vector<CrownTip>& tips, glm::dvec3 low, glm::dvec3 high, double size) {
  const int nx = std::max(1, static_cast<int>(std::ceil((high.x - low.x) / size)));
  const int ny = std::max(1, static_cast<int>(std::ceil((high.y - low.y) / size)));
  std::vector<int> counts(static_cast<std::size_t>(nx) * ny, 0);
  for (const CrownTip& tip : tips) {
    const int i = std::min(nx - 1, static_cast<int>((tip.position.x - low.x) / size));
    const int j = std::min(ny - 1, static_cast<int>((tip.position.y - low.y) / size));
    ++counts[static_cast<std::size_t>(j) * nx + i];
  }
  double sum = 0.0, sum2 = 0.0;
  for (int c : counts) {
    sum += c;
    sum2 += static_cast<double>(c) * c;
  }
  const double mean = sum / counts.size();
  return mean > 0.0 ? std::sqrt(std::max(0.0, sum2 / counts.size() - mean * mean)) / mean : 0.0;
}

}  // namespace

CrownMetrics measure_crown(const std::vector<CrownTip>& tips, double quadrat_size, double crowding_radius) {
  CrownMetrics m;
  m.tips = static_cast<int>(tips.size());
  if (tips.empty()) return m;
  glm::dvec3 low(std::numeric_limits<double>::max()), high(std::numeric_limits<double>::lowest()), centroid(0.0);
  int drooping = 0, downward = 0;
  for (const CrownTip& tip : tips) {
    low = glm::min(low, tip.position);
    high = glm::max(high, tip.position);
    centroid += tip.position / static_cast<double>(tips.size());
    drooping += tip.position.z < tip.branch_base_z;
    downward += tip.direction.z < 0.0;
  }
  m.width = 0.5 * ((high.x - low.x) + (high.y - low.y));
  m.top = high.z;
  m.bottom = low.z;
  m.height = high.z - low.z;
  m.min_x = low.x;
  m.max_x = high.x;
  m.drooping = static_cast<double>(drooping) / tips.size();
  m.downward = static_cast<double>(downward) / tips.size();

  // O(n^2) is fine for the few thousand tips of a seed-000 crown.
  double nearest_sum = 0.0, crowding_sum = 0.0;
  for (std::size_t i = 0; i < tips.size() && tips.size() > 1; ++i) {
    double nearest = std::numeric_limits<double>::max();
    for (std::size_t j = 0; j < tips.size(); ++j) {
      if (i == j) continue;
      const double d = std::hypot(tips[i].position.x - tips[j].position.x, tips[i].position.y - tips[j].position.y);
      nearest = std::min(nearest, d);
      crowding_sum += d < crowding_radius;
    }
    nearest_sum += nearest;
  }
  m.nearest_neighbour = tips.size() > 1 ? nearest_sum / tips.size() : 0.0;
  m.crowding = crowding_sum / tips.size();

  double sum = 0.0, sum2 = 0.0;
  for (const CrownTip& tip : tips) {
    const double r = glm::length(tip.position - centroid);
    sum += r;
    sum2 += r * r;
  }
  const double mean = sum / tips.size();
  const double variance = std::max(0.0, sum2 / tips.size() - mean * mean);
  m.roundness_cv = mean > 0.0 ? std::sqrt(variance) / mean : 0.0;
  m.quadrat_cv = quadrat_cv(tips, low, high, quadrat_size);
  return m;
}

std::vector<CrownTip> crown_tips(const DichotomyTree& tree, int group, int bough_generations) {
  const auto& branches = tree.branches();
  std::vector<CrownTip> result;
  for (int i : tree.tips()) {
    const DichotomyBranch& tip = branches[i];
    if (group >= 0 && tip.group != group) continue;
    int base = i;
    // Up the ancestry, but not onto the start's own first branch (the long root of Figs. 10-14).
    for (int k = 0; k < bough_generations && branches[base].parent >= 0 && branches[branches[base].parent].parent >= 0;
         ++k)
      base = branches[base].parent;
    result.push_back({tip.tip, tree.direction(i), branches[base].base.z});
  }
  return result;
}

}  // namespace heliostand
