#pragma once
// A stand survey: one record per living tree, as read from the survey CSV (docs/formats.md) with every
// missing value imputed. Sizes in metres, DBH in cm, age in years.
#include <filesystem>
#include <string>
#include <vector>

#include "survey/tree_hollow.hpp"

namespace heliostand {

// Which fields of a record were not in the file and were filled in by the survey allometry.
struct ImputedFields {
  bool id = false;
  bool height = false;
  bool dbh = false;
  bool crown_radius = false;
  bool crown_base = false;
  bool age = false;
  bool species = false;
};

struct SurveyRecord {
  std::string id;
  int line = 0;                 // line of the survey file where the record starts
  double x_m = 0, y_m = 0;      // stem position at the ground
  double height_m = 0;
  double dbh_cm = 0;            // diameter at breast height (1.3 m)
  double crown_radius_m = 0;    // mean projected crown radius
  double crown_base_m = 0;      // height of the live-crown base
  double age_years = 0;
  std::string species;
  std::vector<TreeHollow> hollows;  // survey column `hollow` and scenario [[hollow]]; non-empty: a habitat tree
  ImputedFields imputed;
};

struct Survey {
  std::filesystem::path file;
  std::vector<SurveyRecord> trees;
  std::vector<std::string> warnings;  // one per imputed (or ignored) column; the caller logs them
};

}  // namespace heliostand
