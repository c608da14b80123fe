// The culled + far-field approximation against the exact light field on a synthetic plantation
// (the CI-sized version of the 10^5-ball check in docs/performance.md), with the far field's bias correction
// on (the default) and off, at the 4 m cut-off of docs/light.md's figures, and with the default parameters.
#include <gtest/gtest.h>

#include <cmath>

#include "light/reference_light_solver.hpp"
#include "light/synthetic_canopy.hpp"

namespace heliostand {
namespace {

// 64 trees (8 x 8 on 2.5 m), ~94 balls each: far enough across for the far field to matter; 80 receivers.
struct Plantation {
  SyntheticCanopy canopy = make_synthetic_canopy(6000, 3);
  std::vector<std::uint32_t> subsample;
  std::vector<LightSample> truth;
  Plantation() {
    for (std::uint32_t k = 0; k < 80; ++k) subsample.push_back(k * 6000 / 80);
    LightParameters p;
    p.exact = true;
    truth = ReferenceLightSolver(p).solve_for(canopy.balls, subsample);
  }
};

struct Deviation {
  double mean_error = 0, mean_bias = 0;  // mean |approx - exact| and mean (approx - exact): negative = too dark
};

Deviation deviation(const std::vector<LightSample>& truth, const std::vector<LightSample>& approx) {
  Deviation d;
  for (std::size_t k = 0; k < truth.size(); ++k) {
    d.mean_error += std::abs(truth[k].light - approx[k].light) / truth.size();
    d.mean_bias += (approx[k].light - truth[k].light) / truth.size();
  }
  return d;
}

constexpr double figures_cutoff_m = 4.0;  // the cut-off of the figures quoted below

std::vector<LightSample> culled(const Plantation& stand, bool bias_correction) {
  LightParameters p;
  p.cutoff_m = figures_cutoff_m;
  p.far_field_bias_correction = bias_correction;
  return ReferenceLightSolver(p).solve_for(stand.canopy.balls, stand.subsample);
}

// With the correction (read the far field one cell beyond the cut-off, clumping index): 0.0029 with a bias of
// +0.0013 (docs/light.md).
TEST(LightCulling, BiasCorrectedFarFieldKeepsMeanLightWithinFiveThousandthsOfExactWithoutDarkBias) {
  const Plantation stand;
  LightParameters p;
  p.cutoff_m = figures_cutoff_m;
  p.far_field_bias_correction = true;
  ReferenceLightSolver solver(p);
  const auto approx = solver.solve_for(stand.canopy.balls, stand.subsample);
  const Deviation d = deviation(stand.truth, approx);
  EXPECT_LE(d.mean_error, 0.005);
  EXPECT_LE(std::abs(d.mean_bias), 0.004);
  double mean_light = 0;
  for (const auto& s : stand.truth) mean_light += s.light / stand.truth.size();
  EXPECT_LT(mean_light, 0.6);  // a canopy dense enough for the question to matter
  EXPECT_GT(solver.last_statistics().mean_candidates, 100);
  // the far field really carries part of the answer: the near field alone is clearly too bright
  p.far_field = false;
  const auto bright = ReferenceLightSolver(p).solve_for(stand.canopy.balls, stand.subsample);
  EXPECT_GT(deviation(stand.truth, bright).mean_bias, 2 * d.mean_error);
}

// Off (the default until the growth rules were set on the corrected light): the far field read at the cut-off
// with the plain density, as before the correction existed: within the old bound of 0.02, and with its known dark
// bias (0.0086, all of it dark, docs/light.md), which the correction removes.
TEST(LightCulling, UncorrectedFarFieldKeepsMeanLightWithinTwoHundredthsOfExactAndStaysDark) {
  const Plantation stand;
  const auto uncorrected = culled(stand, false);
  const Deviation off = deviation(stand.truth, uncorrected);
  EXPECT_LE(off.mean_error, 0.02);
  EXPECT_LT(off.mean_bias, -0.006);
  EXPECT_GT(-off.mean_bias, 0.9 * off.mean_error);  // nearly all of the error is toward dark
  const Deviation on = deviation(stand.truth, culled(stand, true));
  EXPECT_LT(on.mean_error, off.mean_error / 2);
}

// The default light (the corrected far field at the default cut-off) meets issue 16's goal, mean |error| <= 0.01,
// without the old dark bias (-0.0086 at 4 m, worse at shorter cut-offs).
TEST(LightCulling, DefaultLightIsTheCorrectedFarFieldWithinOneHundredthOfExact) {
  const Plantation stand;
  const LightParameters defaults;
  EXPECT_TRUE(defaults.far_field_bias_correction);
  const auto by_default = ReferenceLightSolver(defaults).solve_for(stand.canopy.balls, stand.subsample);
  const Deviation d = deviation(stand.truth, by_default);
  EXPECT_LE(d.mean_error, 0.01);
  EXPECT_LE(std::abs(d.mean_bias), 0.005);
}

}  // namespace
}  // namespace heliostand
