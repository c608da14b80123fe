#include "stand/calibration.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include <fmt/format.h>

#include "architecture/height_curve.hpp"

namespace heliostand {

const char* to_string(CalibrationStatus status) {
  switch (status) {
    case CalibrationStatus::fitted: return "fitted";
    case CalibrationStatus::height_off: return "height_off";
    case CalibrationStatus::crown_base_off: return "crown_base_off";
    case CalibrationStatus::crown_radius_off: return "crown_radius_off";
    case CalibrationStatus::invalid_target: return "invalid_target";
  }
  return "unknown";
}

ConiferTree grow_calibrated_tree(const SpeciesParameters& species, const TreeCalibration& calibration,
                                 int age_years, glm::dvec3 stem_base, std::uint64_t seed, int tree_id,
                                 const SurveyState& survey) {
  ConiferTree tree(species, calibration, stem_base, seed, tree_id);
  tree.grow_to_age(age_years);
  if (survey.dbh_cm || survey.crown_base_m)
    tree.set_survey_state(survey.dbh_cm.value_or(tree.dbh_cm()), survey.crown_base_m.value_or(tree.crown_base_m()));
  return tree;
}

namespace {

std::optional<std::string> invalid_reason(const SurveyTarget& target) {
  if (target.age_years < 1) return fmt::format("age {} years: expected at least 1", target.age_years);
  if (!(target.height_m > 0.0) || !std::isfinite(target.height_m))
    return fmt::format("height {} m: expected a number > 0", target.height_m);
  if (target.crown_radius_m && (!(*target.crown_radius_m > 0.0) || !std::isfinite(*target.crown_radius_m)))
    return fmt::format("crown radius {} m: expected a number > 0", *target.crown_radius_m);
  if (target.crown_base_m && !(*target.crown_base_m >= 0.0 && *target.crown_base_m < target.height_m))
    return fmt::format("crown base {} m: expected 0 ≤ crown base < height {} m", *target.crown_base_m,
                       target.height_m);
  return std::nullopt;
}

// The elongation scales of the two growths that give Fit::first_scale its line: small enough that laterals stay
// under the minimum parent length (a 60-year-old grows the same 4 200 shoots at 0.02 to 0.2 as at 0.05), far
// enough apart to give a slope.
constexpr double small_scale_probes[2] = {0.05, 0.1};

// The fitting loop, holding what is fixed (species, record, stream) and counting regrowths.
class Fit {
 public:
  Fit(const SpeciesParameters& species, const SurveyTarget& target, std::uint64_t seed, int tree_id)
      : species_(species), target_(target), seed_(seed), tree_id_(tree_id) {}

  ConiferTree grow(const TreeCalibration& calibration) {
    return counted(grow_calibrated_tree(species_, calibration, target_.age_years, {}, seed_, tree_id_,
                                        {target_.dbh_cm, target_.crown_base_m}));
  }
  ConiferTree grow_unpruned(const TreeCalibration& calibration) {
    return counted(grow_calibrated_tree(species_, calibration, target_.age_years, {}, seed_, tree_id_));
  }

  // Crown base falls as first-order branches live longer, one whorl per whole year, and does not depend on
  // the elongation scale (branches die by age alone): bisect whole years on the smallest-possible tree, for the
  // shortest life that leaves a living whorl at or below the record (set_survey_state then prunes to it).
  double fit_growth_stop_years(TreeCalibration calibration, double record) {
    calibration.elongation_scale = 0.05;  // tiny shoots: laterals stay under the minimum parent length, fast
    int low = 1, high = std::max(1, target_.age_years) + 1;  // crown_base(low) ≥ crown_base(high)
    auto crown_base = [&](int years) {
      calibration.growth_stop_years_first_order = years;
      return grow_unpruned(calibration).crown_base_m();
    };
    while (high - low > 1) {
      const int middle = (low + high) / 2;
      (crown_base(middle) > record + 1e-9 ? low : high) = middle;
    }
    return high;
  }

  // Crown radius grows nearly in proportion to the elongation scale: take proportional (secant through the
  // origin) steps, fall back to bisection once the record is bracketed and a step leaves the bracket. The steps
  // start from the species' own scale, unless the record's crown is far smaller than that scale grows
  // (first_scale).
  double fit_elongation_scale(TreeCalibration calibration, double record, double relative_tolerance,
                              int max_regrowths) {
    const double min_scale = 0.02, max_scale = 50.0;
    double low = min_scale, high = max_scale;  // bracket: radius(low) < record < radius(high) once both seen
    bool have_low = false, have_high = false;
    double best_scale = calibration.elongation_scale, best_error = INFINITY;
    double scale = first_scale(calibration, record);
    for (int i = 0; i < max_regrowths; ++i) {
      calibration.elongation_scale = scale;
      ConiferTree tree = grow(calibration);
      const double radius = tree.crown_radius_m();
      const double error = std::abs(radius - record) / record;
      if (error < best_error) {
        best_error = error, best_scale = scale;
        best_tree_.emplace(std::move(tree));
      }
      if (error <= relative_tolerance) break;
      if (radius < record) low = scale, have_low = true;
      else high = scale, have_high = true;
      double next = radius > 0.0 ? scale * record / radius : scale * 2.0;
      if (have_low && have_high && !(next > low && next < high)) next = 0.5 * (low + high);
      next = std::clamp(next, min_scale, max_scale);
      if (next == scale) break;  // pinned at a bound: the record is out of reach
      scale = next;
    }
    return best_scale;
  }

  // Where the fit's steps start. Shoots multiply steeply with the scale once laterals pass the minimum parent
  // length, so a step from the species' scale (1) down to a small record grows a huge crown first: a 60-year-old
  // fitted to a 2 m crown (scale 0.29, 7 000 shoots) grew 570 000 shoots at scale 1, 5.5 s of its 5.6 s fit
  // (docs/performance.md "Establishing old trees"). Two growths at small scales, where laterals stay under that
  // length and a tree of any age is cheap, give the line r = a + b s and on it a guess for the record; below
  // two thirds of the species' scale the steps start there. Above, they start from the species' scale as
  // before, which costs little there and keeps those fits (young plantations, the example stand) as they were.
  double first_scale(TreeCalibration calibration, double record) {
    const double species_scale = calibration.elongation_scale;
    double radius[2];
    for (int k = 0; k < 2; ++k) {
      calibration.elongation_scale = small_scale_probes[k];
      radius[k] = grow(calibration).crown_radius_m();
    }
    const double slope = (radius[1] - radius[0]) / (small_scale_probes[1] - small_scale_probes[0]);
    if (!(slope > 0.0)) return species_scale;
    const double guess = small_scale_probes[1] + (record - radius[1]) / slope;
    return guess < (2.0 / 3.0) * species_scale ? std::max(guess, small_scale_probes[0]) : species_scale;
  }

  // The growth at the scale fit_elongation_scale returned, if it ran: the calibrated tree itself (growth is
  // deterministic, so growing it once more would repeat it exactly).
  std::optional<ConiferTree> take_best_tree() { return std::exchange(best_tree_, std::nullopt); }

  int regrowths() const { return regrowths_; }
  std::size_t largest_regrowth_shoots() const { return largest_shoots_; }

 private:
  const SpeciesParameters& species_;
  const SurveyTarget& target_;
  std::uint64_t seed_;
  int tree_id_;
  int regrowths_ = 0;
  std::size_t largest_shoots_ = 0;
  std::optional<ConiferTree> best_tree_;

  ConiferTree counted(ConiferTree tree) {
    ++regrowths_;
    largest_shoots_ = std::max(largest_shoots_, tree.shoots().size());
    return tree;
  }
};

}  // namespace

CalibrationResult calibrate_tree(const SpeciesParameters& species, const SurveyTarget& target, std::uint64_t seed,
                                 int tree_id, const CalibrationTolerance& tolerance) {
  CalibrationResult result;
  result.calibration.site_asymptote_m = species.site_asymptote_m;
  result.calibration.growth_stop_years_first_order = species.growth_stop_years_first_order;
  if (auto reason = invalid_reason(target)) {
    result.status = CalibrationStatus::invalid_target;
    result.message = "tree " + std::to_string(tree_id) + ": " + *reason;
    return result;
  }
  Fit fit(species, target, seed, tree_id);
  TreeCalibration& calibration = result.calibration;
  calibration.site_asymptote_m = site_asymptote_for(species, target.height_m, target.age_years);
  if (target.crown_base_m)
    calibration.growth_stop_years_first_order = fit.fit_growth_stop_years(calibration, *target.crown_base_m);
  // Aim well inside the tolerance: the final growth must land within it.
  if (target.crown_radius_m)
    calibration.elongation_scale = fit.fit_elongation_scale(calibration, *target.crown_radius_m,
                                                            0.25 * tolerance.crown_radius_relative,
                                                            tolerance.max_crown_radius_regrowths);
  std::optional<ConiferTree> fitted = fit.take_best_tree();
  const ConiferTree tree = fitted ? std::move(*fitted) : fit.grow(calibration);
  result.regrowths = fit.regrowths();
  result.largest_regrowth_shoots = fit.largest_regrowth_shoots();
  result.height_m = tree.height_m();
  result.crown_radius_m = tree.crown_radius_m();
  result.crown_base_m = tree.crown_base_m();
  result.height_error_relative = (result.height_m - target.height_m) / target.height_m;
  if (target.crown_radius_m)
    result.crown_radius_error_relative = (result.crown_radius_m - *target.crown_radius_m) / *target.crown_radius_m;
  if (target.crown_base_m) result.crown_base_error_m = result.crown_base_m - *target.crown_base_m;

  const bool height_ok = std::abs(result.height_error_relative) <= tolerance.height_relative;
  const bool radius_ok = std::abs(result.crown_radius_error_relative) <= tolerance.crown_radius_relative;
  const bool base_ok = std::abs(result.crown_base_error_m) <= tolerance.crown_base_m;
  result.status = !height_ok               ? CalibrationStatus::height_off
                  : !radius_ok             ? CalibrationStatus::crown_radius_off
                  : !base_ok               ? CalibrationStatus::crown_base_off
                                           : CalibrationStatus::fitted;
  result.message = fmt::format(
      "tree {}: {} — height {:.2f} m ({:+.1f} %), crown radius {:.2f} m ({:+.1f} %), crown base {:.2f} m "
      "({:+.2f} m); A = {:.2f} m, elongation scale {:.3f}, first-order growth stop {:.0f} y, {} regrowths",
      tree_id, to_string(result.status), result.height_m, 100.0 * result.height_error_relative,
      result.crown_radius_m, 100.0 * result.crown_radius_error_relative, result.crown_base_m,
      result.crown_base_error_m, calibration.site_asymptote_m, calibration.elongation_scale,
      calibration.growth_stop_years_first_order, result.regrowths);
  return result;
}

}  // namespace heliostand
