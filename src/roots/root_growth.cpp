#include "roots/root_growth.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/geometric.hpp>

#include "core/parallel_for.hpp"
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
  std::size_t count = 0;
  for (const RootSystem* tree : trees) count += tree->segments().size();
  stand.lines.reserve(count);
  for (const RootSystem* tree : trees) {
    stand.offsets.push_back(static_cast<int>(stand.lines.size()));
    for (const RootSegment& segment : tree->segments()) stand.lines.push_back({segment.start, segment.end});
  }
  return stand;
}

namespace {

// Trees whose uptake shares are held at once (about 130 kB for a tree of 1 000 absorbing segments).
constexpr std::size_t trees_per_uptake_chunk = 64;

// The queries of one chunk of buds, with their probes (K per bud, in the buds' order), and which bud each one is.
struct BudQueries {
  std::vector<RootTipQuery> tips;
  std::vector<glm::dvec3> probes;
  std::span<const std::pair<std::size_t, std::size_t>> buds;  // (tree, bud of the tree)
};

RootTipQuery query_of(const RootSystem& tree, const RootBud& bud, std::size_t first_segment) {
  const RootSegment& from = tree.segments()[bud.from_segment];
  RootTipQuery query;
  query.position = from.end;
  query.perception_radius_m = tree.parameters().of(bud.type).perception_radius_m;
  query.excluded[0] = static_cast<int>(first_segment) + bud.from_segment;
  query.excluded[1] = from.parent >= 0 ? static_cast<int>(first_segment) + from.parent : -1;
  return query;
}

// Every bud's probes come from its own stream (tree, year, segment, bud), so the buds of a chunk are drawn in
// parallel and the answer does not depend on the threads.
std::vector<glm::dvec3> probes_of(const RootSystem& tree, const RootBud& bud, int probes_per_tip, int year,
                                  std::uint64_t seed) {
  const RootSegment& from = tree.segments()[bud.from_segment];
  RandomStream random(seed, {static_cast<std::uint64_t>(tree.tree_id()), static_cast<std::uint64_t>(year),
                             organ_root_probe, from.id, static_cast<std::uint64_t>(bud.ordinal)});
  return draw_moisture_probes(random, probes_per_tip);
}

glm::dvec3 direction_of(const RootSystem& tree, const RootBud& bud, const RootFieldSample& sample) {
  TropismVectors vectors;
  vectors.inherited = bud.inherited;
  vectors.diagravitropic = horizontal_of(bud.inherited, bud.horizontal_fallback);
  vectors.moisture_pull = sample.moisture_pull;
  vectors.contact_avoidance = sample.contact_avoidance;
  return compose_direction(tree.parameters().of(bud.type).tropisms, vectors);
}

// Every bud of every tree (each tree's from its own streams: in parallel), in the trees' order.
struct StandBuds {
  std::vector<std::vector<RootBud>> of_tree;
  std::vector<std::pair<std::size_t, std::size_t>> every;  // (tree, bud of the tree), tree after tree
};

StandBuds buds_of(std::span<RootSystem* const> trees, int year, std::uint64_t seed) {
  StandBuds buds;
  buds.of_tree.resize(trees.size());
  parallel_for(trees.size(), [&](std::size_t t) { buds.of_tree[t] = trees[t]->buds(year, seed); });
  for (std::size_t t = 0; t < trees.size(); ++t)
    for (std::size_t b = 0; b < buds.of_tree[t].size(); ++b) buds.every.emplace_back(t, b);
  return buds;
}

// The field of the year: the roots as they all stand before any of them grows, seen in the trees' own lists (not
// copied), and the widest perception radius of any bud.
RootFieldYear field_of(std::span<RootSystem* const> trees, const StandBuds& buds, const SoilGrid& soil) {
  RootFieldYear field;
  field.soil = &soil;
  for (std::size_t t = 0; t < trees.size(); ++t) {
    field.segments.append(trees[t]->segments());
    for (const RootBud& bud : buds.of_tree[t])
      field.widest_perception_radius_m =
          std::max(field.widest_perception_radius_m, trees[t]->parameters().of(bud.type).perception_radius_m);
  }
  return field;
}

// The composed direction V of every bud: the field at every bud, a chunk of buds per query, so that the queries and
// their probes (K per bud) never exist for all buds at once. One K for the whole year: the first tree's (species may
// differ in everything else).
std::vector<std::vector<glm::dvec3>> bud_directions(std::span<RootSystem* const> trees, const StandBuds& buds,
                                                    const RootFieldYear& field, RootFieldSolver& solver, int year,
                                                    std::uint64_t seed, std::size_t buds_per_query) {
  const int probes_per_tip = trees.empty() ? 0 : trees[0]->parameters().moisture_probes;
  const auto per_tip = static_cast<std::size_t>(probes_per_tip);
  std::vector<std::vector<glm::dvec3>> directions(trees.size());
  for (std::size_t t = 0; t < trees.size(); ++t) directions[t].resize(buds.of_tree[t].size());
  BudQueries queries;
  for (std::size_t first = 0; first < buds.every.size(); first += buds_per_query) {
    queries.buds = std::span(buds.every).subspan(first, std::min(buds_per_query, buds.every.size() - first));
    queries.tips.resize(queries.buds.size());
    queries.probes.resize(queries.buds.size() * per_tip);
    parallel_for(queries.buds.size(), [&](std::size_t q) {
      const auto [t, b] = queries.buds[q];
      const RootBud& bud = buds.of_tree[t][b];
      queries.tips[q] = query_of(*trees[t], bud, field.segments.first_of_part(t));
      const std::vector<glm::dvec3> drawn = probes_of(*trees[t], bud, probes_per_tip, year, seed);
      std::copy(drawn.begin(), drawn.end(), queries.probes.begin() + static_cast<std::ptrdiff_t>(q * per_tip));
    });
    const std::vector<RootFieldSample> samples = solver.query(queries.tips, queries.probes, probes_per_tip);
    parallel_for(samples.size(), [&](std::size_t q) {
      const auto [t, b] = queries.buds[q];
      directions[t][b] = direction_of(*trees[t], buds.of_tree[t][b], samples[q]);
    });
  }
  return directions;
}

}  // namespace

std::vector<double> take_up_in_order(std::span<RootSystem* const> trees, SoilGrid& soil) {
  // What each segment takes of its vertices does not depend on the soil's values: a chunk of trees finds its shares
  // in parallel, then depletes the soil tree after tree, the same arithmetic in the same order as one tree at a time.
  std::vector<double> taken(trees.size());
  std::vector<std::vector<SoilGrid::DepletionShares>> shares(std::min(trees.size(), trees_per_uptake_chunk));
  for (std::size_t first = 0; first < trees.size(); first += trees_per_uptake_chunk) {
    const std::size_t count = std::min(trees_per_uptake_chunk, trees.size() - first);
    parallel_for(count, [&](std::size_t t) { shares[t] = trees[first + t]->uptake_shares(soil); });
    for (std::size_t t = 0; t < count; ++t) taken[first + t] = RootSystem::take_up(soil, shares[t]);
  }
  return taken;
}

RootYearSummary grow_roots(std::span<RootSystem* const> trees, SoilGrid& soil, RootFieldSolver& solver, int year,
                           std::uint64_t seed, std::size_t buds_per_query) {
  RootYearSummary summary;
  buds_per_query = std::max<std::size_t>(buds_per_query, 1);

  // 1. Buds of every tree, and the field of the year as the roots stand before any grows.
  const StandBuds buds = buds_of(trees, year, seed);
  const RootFieldYear field = field_of(trees, buds, soil);
  solver.begin_year(field);
  // 2. The field at every bud, and the direction each bud grows in.
  const auto directions = bud_directions(trees, buds, field, solver, year, seed, buds_per_query);
  solver.end_year();

  // 3. New segments in the composed direction V (each tree its own: in parallel; the soil is only read).
  std::vector<int> removed(trees.size(), 0);
  parallel_for(trees.size(), [&](std::size_t t) {
    RootSystem& tree = *trees[t];
    for (std::size_t b = 0; b < buds.of_tree[t].size(); ++b)
      tree.add_segment(buds.of_tree[t][b], directions[t][b], year, soil);
    // 4. Close the year.
    removed[t] = tree.finish_year(year);
  });
  summary.new_segments += static_cast<int>(buds.every.size());
  for (int r : removed) summary.removed_segments += r;

  // 5. Uptake, tree after tree.
  summary.moisture_taken_by_tree = take_up_in_order(trees, soil);
  for (double taken : summary.moisture_taken_by_tree) summary.moisture_taken += taken;
  return summary;
}

}  // namespace heliostand::roots
