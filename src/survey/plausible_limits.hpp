#pragma once
// Physical limits of survey values: a value beyond them is a typing or unit slip (a height in cm, a DBH in
// mm without saying so) or garbage, and some would overflow the model (a 1e308-m tree). They are errors
// before anything runs. Limits are generous — the largest trees measured — so no real tree is refused.
// docs/formats.md lists them with their sources.
#include <optional>
#include <string_view>

#include "survey/survey_columns.hpp"

namespace heliostand {

// Limits the scenario shares with the survey: a plot's corners and the stand age at the survey.
constexpr double max_coordinate_m = 1e7;     // UTM northings stay below 10,000 km
constexpr double max_tree_age_years = 5000;  // the oldest known non-clonal tree is about 4,850 years old

struct PlausibleLimit {
  double max;             // in the column's canonical unit; values above are errors
  std::string_view why;   // the fact behind the limit, quoted in the message
};

// The upper limit of a numeric column (positions: of the magnitude), or nothing for a column without one.
std::optional<PlausibleLimit> plausible_limit(SurveyColumn column);

// Slenderness (height / DBH, both in m) outside this range on a tree taller than slenderness_min_height_m
// draws a warning, not an error: open-grown veterans reach 20 and suppressed poles 150, but a ratio of 5 or
// 400 is more often a slip in the DBH's unit than a tree. Saplings are exempt: near breast height the ratio
// of any tree is large.
constexpr double slenderness_min = 10.0;
constexpr double slenderness_max = 200.0;
constexpr double slenderness_min_height_m = 5.0;

}  // namespace heliostand
