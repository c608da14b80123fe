#pragma once
// Grown root systems of a few trees in one soil, and an apex at every segment end, for the root-contact field's
// backend tests (OpenCL against the reference, the reference on any number of threads).
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "rng/random_stream.hpp"
#include "roots/reference_root_field_solver.hpp"
#include "roots/root_growth.hpp"

namespace heliostand::roots::test_stands {

struct GrownStand {
  SoilGrid soil{{{-4.0, -4.0, -3.0}, 0.25, {32, 32, 12}}, 1.0, 0.5};
  std::vector<RootSystem> trees;
};

// Three tap-rooted trees side by side, grown `years` on the reference solver in moisture falling with depth.
inline GrownStand grown_stand(int years, std::uint64_t seed) {
  GrownStand stand;
  stand.soil.fill_gradient(SoilField::moisture, 0, 1.0, 0.1);
  for (int t = 0; t < 3; ++t)
    stand.trees.emplace_back(t, glm::dvec3(-1.0 + 1.0 * t, 0.3 * t, 0.0), tap_rooted_conifer(), 0);
  std::vector<RootSystem*> pointers;
  for (RootSystem& tree : stand.trees) pointers.push_back(&tree);
  ReferenceRootFieldSolver solver;
  for (int year = 1; year <= years; ++year) grow_roots(pointers, stand.soil, solver, year, seed);
  return stand;
}

// Every segment end of the stand as an apex (as in growth: it excludes its own segment and that one's parent),
// with a perception radius of 0.1-0.4 m and its moisture probes.
struct ApexQueries {
  StandSegments segments;
  std::vector<RootTipQuery> tips;
  std::vector<glm::dvec3> probes;
  static constexpr int probes_per_tip = 16;

  RootFieldInput input(const SoilGrid& soil) const { return {segments.lines, tips, probes, probes_per_tip, &soil}; }
};

inline ApexQueries apices_at_every_segment_end(GrownStand& stand, std::uint64_t seed) {
  ApexQueries queries;
  std::vector<RootSystem*> pointers;
  for (RootSystem& tree : stand.trees) pointers.push_back(&tree);
  queries.segments = gather_segments(pointers);
  RandomStream random(seed, {99});
  for (std::size_t t = 0; t < stand.trees.size(); ++t)
    for (std::size_t s = 0; s < stand.trees[t].segments().size(); ++s) {
      const RootSegment& segment = stand.trees[t].segments()[s];
      RootTipQuery tip;
      tip.position = segment.end;
      tip.perception_radius_m = random.uniform(0.1, 0.4);
      tip.excluded[0] = queries.segments.offsets[t] + static_cast<int>(s);
      tip.excluded[1] = segment.parent >= 0 ? queries.segments.offsets[t] + segment.parent : -1;
      queries.tips.push_back(tip);
      const auto drawn = draw_moisture_probes(random, ApexQueries::probes_per_tip);
      queries.probes.insert(queries.probes.end(), drawn.begin(), drawn.end());
    }
  return queries;
}

}  // namespace heliostand::roots::test_stands
