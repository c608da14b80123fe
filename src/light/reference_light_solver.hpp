#pragma once
// The oracle: plain double-precision C++, one receiving ball at a time, every sky patch tested against
// every occluder with seed 000's ray test. Exact mode tests every other ball of the stand (and, periodic,
// its images in the 8 neighbouring copies of the plot); culled mode tests the FLANN near-field candidates
// and multiplies in the far-field attenuation. The receivers (culled: their tiles) share the worker threads
// (core/parallel_for.hpp); each sample is computed exactly as on one thread, so the answers do not depend on them.
#include "light/light_parameters.hpp"
#include "light/light_solver.hpp"

namespace heliostand {

class CelestialSphere;
struct PlotTorus;

class ReferenceLightSolver final : public LightSolver {
 public:
  explicit ReferenceLightSolver(const LightParameters& parameters);
  std::string name() const override { return "reference"; }
  std::vector<LightSample> solve_for(std::span<const LeafBall> balls,
                                     std::span<const std::uint32_t> receivers) override;

 private:
  // Each writes statistics_ (cleared by solve_for) as it goes.
  std::vector<LightSample> solve_exact(std::span<const LeafBall> balls, std::span<const std::uint32_t> receivers,
                                       const CelestialSphere& sky, const PlotTorus& torus);
  std::vector<LightSample> solve_culled(std::span<const LeafBall> balls, std::span<const std::uint32_t> receivers,
                                        const CelestialSphere& sky, const PlotTorus& torus);

  LightParameters parameters_;
};

}  // namespace heliostand
