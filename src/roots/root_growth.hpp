#pragma once
// One year of root growth for every tree of a stand (seed 003, all in one soil: docs/roots.md): all apices perceive
// the soil and the roots of ALL trees (as they stood at the start of the year, so the result does not depend
// on the order trees are visited), grow one segment each, age, die, and take up moisture and nutrients.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "rng/random_stream.hpp"
#include "roots/root_field_solver.hpp"
#include "roots/root_system.hpp"
#include "roots/soil_grid.hpp"

namespace heliostand::roots {

struct RootYearSummary {
  int new_segments = 0;
  int removed_segments = 0;          // died of old age (with what they carried)
  double moisture_taken = 0.0;       // Σ over vertices of moisture removed by uptake
  std::vector<double> moisture_taken_by_tree;  // in the order of `trees`
};

// Buds per query of the root-contact field: what the year's queries and moisture probes hold at once (with 16
// probes about 0.8 KiB a bud on the host and 0.3 KiB on the device, ~27 + 10 MB per query), and on a GPU enough
// work-items to fill it.
inline constexpr std::size_t default_buds_per_query = std::size_t{1} << 15;

// Grows every tree one year: buds → root-contact field (begun once for the stand's segments, then queried
// `buds_per_query` buds at a time) → new segments → finish_year → uptake. The answer does not depend on
// `buds_per_query`. Soil recharge is the caller's step (SoilGrid::recharge), once per year.
RootYearSummary grow_roots(std::span<RootSystem* const> trees, SoilGrid& soil, RootFieldSolver& solver, int year,
                           std::uint64_t seed, std::size_t buds_per_query = default_buds_per_query);

// The year's uptake (step 5 of grow_roots): each tree's young segments deplete the soil, tree after tree in the
// order given (depletion multiplies vertex values, so the soil left does not depend on the order; the split of the
// amount between trees sharing a vertex does). Returns the moisture each tree took, in that order.
std::vector<double> take_up_in_order(std::span<RootSystem* const> trees, SoilGrid& soil);

// K probe offsets (units of the perception radius) for one bud: K/2 directions uniform on the sphere at
// radius fractions uniform in the ball, each cast together with its opposite ("antithetic" pairs), so a
// uniform moisture field pulls nowhere and only the moisture difference across the sphere steers.
std::vector<glm::dvec3> draw_moisture_probes(RandomStream& random, int count);

// All living segments of the stand, tree after tree; `offsets[t]` is tree t's first index.
struct StandSegments {
  std::vector<RootSegmentLine> lines;
  std::vector<int> offsets;
};
StandSegments gather_segments(std::span<RootSystem* const> trees);

}  // namespace heliostand::roots
