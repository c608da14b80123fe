#pragma once
// Physical limits of survey values: a value beyond them is a typing or unit slip (a height in cm, a DBH in
// mm without saying so) or garbage, and some would overflow the model (a 1e308-m tree). They are errors
// before anything runs. Limits are generous — the largest trees measured — so no real tree is refused.
// docs/formats.md lists them with their sources.
#include <optional>
#include <string_view>

#include "survey/survey_columns.hpp"

namespace heliostand {

// Limits the scenario shares with the survey (a plot's corners, the stand age, a site's asymptotic height, a
// DBH class, ...): one fact, one constant. The sources are in plausible_limit()'s reasons.
constexpr double max_coordinate_m = 1e7;     // UTM northings stay below 10,000 km
constexpr double max_tree_age_years = 5000;  // the oldest known non-clonal tree is about 4,850 years old
constexpr double max_tree_height_m = 130;    // the tallest measured tree, a coast redwood, is 116 m
constexpr double max_dbh_cm = 1500;          // the thickest measured stems are about 11-12 m across
constexpr double max_crown_radius_m = 30;    // the widest measured crowns are about 60 m across

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
