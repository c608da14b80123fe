#pragma once
// Per-tree calibration to a survey record (seed 001 §3.4: "each tree's growth parameters were fitted to its
// record, then each tree was grown one by one"). From planting (age 0) to the survey age:
//   height       — eq. 1's asymptote A solved in closed form, so the height is met exactly;
//   crown base   — the first-order growth-stop years (eq. 12 base) searched over whole years (best effort:
//                  crown base moves in steps of one whorl, i.e. one year's height growth);
//   crown radius — the elongation scale, by safeguarded secant steps on full regrowths.
// A tree that cannot be fitted is reported with how far off it is; nothing throws.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include <glm/vec3.hpp>

#include "architecture/conifer_tree.hpp"
#include "architecture/species.hpp"

namespace heliostand {

struct SurveyTarget {
  int age_years = 0;                     // tree age at the survey (years since planting)
  double height_m = 0;
  std::optional<double> crown_radius_m;  // projected crown radius (half the surveyed crown diameter)
  std::optional<double> crown_base_m;    // live-crown base height
  std::optional<double> dbh_cm;          // the tree starts with it (not fitted: DBH is state, not shape)
};

// What the survey fixes directly on the grown tree (ConiferTree::set_survey_state).
struct SurveyState {
  std::optional<double> dbh_cm;
  std::optional<double> crown_base_m;
};

struct CalibrationTolerance {
  double height_relative = 0.05;
  double crown_radius_relative = 0.02;
  double crown_base_m = 0.5;            // the crown base is set exactly (set_survey_state); a guard
  int max_crown_radius_regrowths = 16;
};

enum class CalibrationStatus {
  fitted,                   // every given target within tolerance
  height_off,               // the height misses its tolerance (eq. 1 is solved exactly, so this is a bug guard)
  crown_base_off,           // height and crown radius fitted; crown base beyond its tolerance
  crown_radius_off,         // no elongation scale in range brings the crown radius within tolerance
  invalid_target,           // the record cannot describe a tree (age < 1, height ≤ 0, crown base ≥ height, ...)
};

struct CalibrationResult {
  TreeCalibration calibration;
  CalibrationStatus status = CalibrationStatus::invalid_target;
  // What the calibrated tree reaches at the survey age, and how far that is from the record.
  double height_m = 0;
  double crown_radius_m = 0;
  double crown_base_m = 0;
  double height_error_relative = 0;        // (reached - record) / record
  double crown_radius_error_relative = 0;  // 0 when the record has no crown radius
  double crown_base_error_m = 0;           // reached - record; 0 when the record has no crown base
  int regrowths = 0;                       // full growths from planting the fit needed
  std::size_t largest_regrowth_shoots = 0; // the most shoots one of them grew: what the fit cost in time and memory
  std::string message;                     // one line: what was fitted, or what is off and by how much

  // Height and crown radius within tolerance: the tree may be used in the stand.
  bool usable() const { return status == CalibrationStatus::fitted || status == CalibrationStatus::crown_base_off; }
};

const char* to_string(CalibrationStatus status);

CalibrationResult calibrate_tree(const SpeciesParameters& species, const SurveyTarget& target, std::uint64_t seed,
                                 int tree_id, const CalibrationTolerance& tolerance = {});

// The tree grown from planting to `age_years` with the given calibration (the same stream as calibration used,
// so it matches what calibrate_tree measured; the stem base only moves the tree).
// With `survey`, the record's DBH and crown base are set on the grown tree (ConiferTree::set_survey_state).
ConiferTree grow_calibrated_tree(const SpeciesParameters& species, const TreeCalibration& calibration,
                                 int age_years, glm::dvec3 stem_base, std::uint64_t seed, int tree_id,
                                 const SurveyState& survey = {});

}  // namespace heliostand
