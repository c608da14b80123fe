#pragma once
// The light field of seed 000 (Kanamaru et al.): for every leaf ball, the sky light that reaches it
// through all other leaf balls of the stand, and the direction it comes from. Two implementations
// (the OpenMM pattern): ReferenceLightSolver, the plain C++ oracle, and OpenCLLightSolver, the default.
// make_light_solver() (light/make_light_solver.hpp) picks the one of the run's compute backend (--device).
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "light/leaf_ball.hpp"

namespace heliostand {

struct LightSample {
  double light = 1.0;                 // Σ B S / Σ B0 S, in 0..1
  // normalize(Σ N B S). When the light is balanced so that |Σ N B S| <= 1e-5 Σ B0 S (e.g. a lone ball
  // with C1 = C2) there is no preferred direction and the vector is (0, 0, 0): heliotropism does nothing.
  glm::dvec3 vector{0.0, 0.0, 1.0};
};

// What the last solve cost, for benchmarks and logs (wall-clock seconds).
struct LightSolveStatistics {
  double setup_seconds = 0;       // k-d tree, candidate lists, far-field grid (culled mode); 0 in exact mode
  double evaluate_seconds = 0;    // the per-ball shading itself (incl. device transfers)
  // Parts of setup_seconds (culled mode), to say where the time goes (docs/performance.md).
  double search_seconds = 0;      // k-d tree and near-field candidate lists
  double far_field_seconds = 0;   // far-field density and optical-depth table
  double mean_candidates = 0;     // near-field occluders per ball (culled) or all other balls (exact)
  double mean_tile_candidates = 0;  // culled: candidates each ball scans (the shells of its tile's list it needs)
  // Culled with a far field: the edge of its cells (m), LightParameters::far_field_cell_m unless a table at that
  // size would exceed far_field_table_mb, when the cells are made coarser. 0 without a far field.
  double far_field_cell_m = 0;
};

class LightSolver {
 public:
  virtual ~LightSolver() = default;
  virtual std::string name() const = 0;  // "reference" or "opencl:<device>"
  // One sample per ball, in the order given.
  std::vector<LightSample> solve(std::span<const LeafBall> balls);
  // Samples for the balls listed in `receivers` only (indices into `balls`), shaded by all `balls`.
  // Used to check or time a large stand on a subsample.
  virtual std::vector<LightSample> solve_for(std::span<const LeafBall> balls,
                                             std::span<const std::uint32_t> receivers) = 0;
  // Each group of balls lit as if it stood alone: group g is balls[group_start[g] .. group_start[g+1]), shaded by
  // its own balls only (the open-grown light of every tree of a stand). group_start runs from 0 to balls.size().
  // Solved group by group here; the OpenCL solver lights all groups in one launch.
  virtual std::vector<LightSample> solve_each_alone(std::span<const LeafBall> balls,
                                                    std::span<const std::size_t> group_start);
  // The stand's light (this solver on all `balls`) and each group's light alone (`alone` on the groups, as
  // solve_each_alone) in one pass, where this solver can do both at once; std::nullopt where it cannot (the caller
  // then calls solve and alone.solve_each_alone). The OpenCL solver does both in one pass for a culled stand solve
  // with an exact open-plot `alone` on the same device (cl/light.cl light_culled_and_alone).
  struct StandAndAlone {
    std::vector<LightSample> stand;
    std::vector<LightSample> alone;
  };
  virtual std::optional<StandAndAlone> solve_with_each_alone(std::span<const LeafBall> balls,
                                                             std::span<const std::size_t> group_start,
                                                             const LightSolver& alone);
  const LightSolveStatistics& last_statistics() const { return statistics_; }

 protected:
  // Throws std::out_of_range when a receiver index is not a ball of `balls`.
  static void check_receivers(std::span<const LeafBall> balls, std::span<const std::uint32_t> receivers);
  // Throws std::invalid_argument unless group_start rises from 0 to balls.size().
  static void check_groups(std::span<const LeafBall> balls, std::span<const std::size_t> group_start);
  LightSolveStatistics statistics_;
};

}  // namespace heliostand
