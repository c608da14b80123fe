#pragma once
// The seed-003 root demonstrations as runnable experiments (Ohshida, Muraoka, Chiba, §2.2 Figs. 4–6):
// a tap-rooted seedling (or two) grown for 15 generations (years) in a soil box, with one tropism
// coefficient of the laterals varied. Shared by the validation tests and the depth-profile report.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "roots/root_field_solver.hpp"
#include "roots/root_parameters.hpp"
#include "roots/root_system.hpp"
#include "roots/soil_grid.hpp"

namespace heliostand::roots::validation {

struct RootExperiment {
  RootParameters parameters = tap_rooted_conifer();
  SoilGridGeometry soil{{-4.0, -4.0, -3.0}, 0.25, {32, 32, 12}};  // 8 m × 8 m × 3 m, surface at z = 0
  bool moisture_gradient_x = false;  // seed Fig. 4: moisture 1.0 at the west face → 0.0 at the east face
  std::vector<double> moisture_layer_bottoms_m;  // optional layered moisture (SoilGrid::fill_layers)
  std::vector<double> moisture_layer_values;
  std::vector<glm::dvec3> collars{{0.0, 0.0, 0.0}};
  int years = 15;                     // the seed's 15 generations
  std::uint64_t seed = 1;
  bool recharge = true;               // yearly recharge (SoilRecharge defaults) after uptake
  // false: each tree is grown alone (sharing only the soil), blind to the other trees' roots — the
  // counterfactual that isolates contact avoidance across trees.
  bool trees_feel_each_other = true;
};

struct RootExperimentResult {
  std::vector<RootSystem> trees;
  SoilGrid soil;
};

RootExperimentResult run_experiment(const RootExperiment& experiment, RootFieldSolver& solver);

// The experiment with the laterals' `which` coefficient set to `value` (others rescaled to keep Σ = 1).
RootExperiment with_lateral_tropism(RootExperiment experiment, Tropism which, double value);

}  // namespace heliostand::roots::validation
