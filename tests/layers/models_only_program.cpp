// A program linked against the models alone (heliostand_models: light, architecture, roots, coupling, hollow and
// the layers below them; no VTK, no toml++, no stand, no io): it grows one conifer for five years in its own light
// and prints its height and number of leaf balls. CTest layers.models_link_alone runs it, which proves that the
// models build and link without the libraries above them.
#include <cstdio>
#include <vector>

#include "architecture/conifer_tree.hpp"
#include "light/reference_light_solver.hpp"

int main() {
  using namespace heliostand;
  ConiferTree tree(SpeciesParameters{}, TreeCalibration{}, {0.0, 0.0, 0.0}, 7, 1);
  tree.grow_to_age(5);
  const std::vector<LeafBall> balls = tree.leaf_balls();
  ReferenceLightSolver solver(LightParameters{});
  const std::vector<LightSample> light = solver.solve(balls);
  double sum = 0;
  for (const LightSample& sample : light) sum += sample.light;
  const double mean = light.empty() ? 0.0 : sum / static_cast<double>(light.size());
  std::printf("height %.3f m, %zu leaf balls, mean light %.3f\n", tree.height_m(), balls.size(), mean);
  return balls.empty() || !(mean > 0.0 && mean <= 1.0) ? 1 : 0;
}
