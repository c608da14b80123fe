#include "root_experiments.hpp"

#include "roots/root_growth.hpp"

namespace heliostand::roots::validation {

RootExperimentResult run_experiment(const RootExperiment& experiment, RootFieldSolver& solver) {
  RootExperimentResult result{{}, SoilGrid(experiment.soil, 1.0, 0.5)};
  if (experiment.moisture_gradient_x) result.soil.fill_gradient(SoilField::moisture, 0, 1.0, 0.0);
  if (!experiment.moisture_layer_values.empty())
    result.soil.fill_layers(SoilField::moisture, experiment.moisture_layer_bottoms_m, experiment.moisture_layer_values);
  constexpr int planting_year = 0;
  for (std::size_t t = 0; t < experiment.collars.size(); ++t)
    result.trees.emplace_back(static_cast<int>(t), experiment.collars[t], experiment.parameters, planting_year);
  std::vector<RootSystem*> trees;
  for (RootSystem& tree : result.trees) trees.push_back(&tree);
  SoilRecharge recharge;
  for (int year = planting_year + 1; year <= planting_year + experiment.years; ++year) {
    if (experiment.trees_feel_each_other) {
      grow_roots(trees, result.soil, solver, year, experiment.seed);
    } else {
      for (RootSystem* tree : trees) grow_roots(std::span(&tree, 1), result.soil, solver, year, experiment.seed);
    }
    if (experiment.recharge) result.soil.recharge(recharge);
  }
  return result;
}

RootExperiment with_lateral_tropism(RootExperiment experiment, Tropism which, double value) {
  // The demonstration laterals: inherited direction and diagravitropism only, so the varied tropism is
  // the only sensing term; its weight is taken from α (the inherited direction gives way to it).
  TropismWeights weights{.alpha = 0.7, .gamma = 0.3};
  double* fields[] = {&weights.alpha, &weights.beta, &weights.gamma, &weights.delta, &weights.epsilon};
  *fields[static_cast<int>(which)] += value;
  weights.alpha -= value;
  experiment.parameters.of(RootType::lateral).tropisms = weights;
  return experiment;
}

}  // namespace heliostand::roots::validation
