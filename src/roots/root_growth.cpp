#include "roots/root_growth.hpp"

#include <cmath>

#include <glm/geometric.hpp>

#include "geometry/angles.hpp"
#include "roots/root_direction.hpp"

namespace heliostand::roots {

std::vector<glm::dvec3> draw_moisture_probes(RandomStream& random, int count) {
  std::vector<glm::dvec3> probes;
  probes.reserve(count);
  for (int k = 0; k + 1 < count; k += 2) {
    const double z = random.uniform(-1.0, 1.0);
    const double azimuth = random.uniform(0.0, 2.0 * pi);
    const double ring = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double reach = std::cbrt(1.0 - random.uniform());  // (0, 1], uniform in the ball's volume
    const glm::dvec3 probe = reach * glm::dvec3(ring * std::cos(azimuth), ring * std::sin(azimuth), z);
    probes.push_back(probe);
    probes.push_back(-probe);
  }
  return probes;
}

StandSegments gather_segments(std::span<RootSystem* const> trees) {
  StandSegments stand;
  for (const RootSystem* tree : trees) {
    stand.offsets.push_back(static_cast<int>(stand.lines.size()));
    for (const RootSegment& segment : tree->segments()) stand.lines.push_back({segment.start, segment.end});
  }
  return stand;
}

RootYearSummary grow_roots(std::span<RootSystem* const> trees, SoilGrid& soil, RootFieldSolver& solver, int year,
                           std::uint64_t seed) {
  RootYearSummary summary;
  const StandSegments stand = gather_segments(trees);

  // 1. Buds of every tree, each with its perception query and probes.
  std::vector<std::vector<RootBud>> buds(trees.size());
  std::vector<RootTipQuery> queries;
  std::vector<glm::dvec3> probes;
  // One K for the whole solve: the first tree's (species may differ in everything else).
  const int probes_per_tip = trees.empty() ? 0 : trees[0]->parameters().moisture_probes;
  for (std::size_t t = 0; t < trees.size(); ++t) {
    const RootSystem& tree = *trees[t];
    buds[t] = tree.buds(year, seed);
    for (const RootBud& bud : buds[t]) {
      const RootSegment& from = tree.segments()[bud.from_segment];
      RootTipQuery query;
      query.position = from.end;
      query.perception_radius_m = tree.parameters().of(bud.type).perception_radius_m;
      query.excluded[0] = stand.offsets[t] + bud.from_segment;
      query.excluded[1] = from.parent >= 0 ? stand.offsets[t] + from.parent : -1;
      queries.push_back(query);
      RandomStream random(seed, {static_cast<std::uint64_t>(tree.tree_id()), static_cast<std::uint64_t>(year),
                                 organ_root_probe, from.id, static_cast<std::uint64_t>(bud.ordinal)});
      const std::vector<glm::dvec3> drawn = draw_moisture_probes(random, probes_per_tip);
      probes.insert(probes.end(), drawn.begin(), drawn.end());
    }
  }

  // 2. One field solve for the whole stand.
  RootFieldInput input;
  input.segments = stand.lines;
  input.tips = queries;
  input.probes = probes;
  input.probes_per_tip = probes_per_tip;
  input.soil = &soil;
  const std::vector<RootFieldSample> field = solver.solve(input);

  // 3. New segments in the composed direction V.
  std::size_t q = 0;
  for (std::size_t t = 0; t < trees.size(); ++t) {
    RootSystem& tree = *trees[t];
    for (const RootBud& bud : buds[t]) {
      const RootFieldSample& sample = field[q++];
      TropismVectors vectors;
      vectors.inherited = bud.inherited;
      vectors.diagravitropic = horizontal_of(bud.inherited, bud.horizontal_fallback);
      vectors.moisture_pull = sample.moisture_pull;
      vectors.contact_avoidance = sample.contact_avoidance;
      tree.add_segment(bud, compose_direction(tree.parameters().of(bud.type).tropisms, vectors), year, soil);
      ++summary.new_segments;
    }
    // 4. Close the year.
    summary.removed_segments += tree.finish_year(year);
  }

  // 5. Uptake, tree after tree (depletion multiplies vertex values, so the soil it leaves does not
  // depend on the order; only the split of the amount between trees sharing a voxel does).
  for (RootSystem* tree : trees) {
    const double taken = tree->take_up(soil);
    summary.moisture_taken_by_tree.push_back(taken);
    summary.moisture_taken += taken;
  }
  return summary;
}

}  // namespace heliostand::roots
