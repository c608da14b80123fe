#pragma once
// Seed 000's light rule (Kanamaru et al. 1991) behind the stand's LightSolver interface, so the seed's growth loop
// (architecture/kanamaru_growth.hpp) lights its tree the way the stand lights its balls: through a LightSolver.
// The rule differs from the stand's in one point: a leaf ball that contains the receiving ball's centre has no
// projection on the receiver's celestial sphere (Fig. 3), so it casts no shadow on it. Every patch ray that can
// reach another ball is tested against it exactly (no culling, no far field: branch lengths are not metres).
#include <cstddef>
#include <span>
#include <vector>

#include "light/celestial_sphere.hpp"
#include "light/light_parameters.hpp"
#include "light/light_solver.hpp"

namespace heliostand {

// Seed 000's light of balls[receiver] through all the other balls, where a ball containing the receiver's centre
// casts no shadow on it.
LightSample kanamaru_light(const CelestialSphere& sky, std::span<const LeafBall> balls, std::size_t receiver,
                           double transmittance);

class KanamaruLightSolver final : public LightSolver {
 public:
  // `enclosing_balls_shade` true: the stand's rule instead (ReferenceLightSolver: an enclosing ball shades in every
  // direction), for the experiments that compare the two.
  KanamaruLightSolver(const LightParameters& parameters, bool enclosing_balls_shade);
  std::string name() const override { return enclosing_balls_shade_ ? "kanamaru (stand rule)" : "kanamaru"; }
  // The receivers are split over up to 8 threads (fewer where no more can start); each receiver's answer is
  // independent of the others.
  std::vector<LightSample> solve_for(std::span<const LeafBall> balls,
                                     std::span<const std::uint32_t> receivers) override;

 private:
  LightParameters parameters_;
  bool enclosing_balls_shade_;
};

}  // namespace heliostand
