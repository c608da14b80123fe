#pragma once
// How a survey file is laid out, as the scenario states it ([stand] survey_separator, survey_units,
// multi_stem; docs/formats.md). The defaults read the tree lists heliostand writes and most others.
#include <map>
#include <string>

#include "core/named_choice.hpp"
#include "survey/field_separator.hpp"
#include "survey/survey_columns.hpp"

namespace heliostand {

// Stems recorded within 1 cm of each other: a typing slip in most plantations (refused), the stems of one
// multi-stemmed tree in coppice and tropical plots (kept as separate trees, or merged into one).
enum class MultiStemPolicy { refuse, separate, merge };
// The names of the scenario key stand.multi_stem.
inline constexpr NamedChoices<MultiStemPolicy, 3> multi_stem_policy_names{
    {{MultiStemPolicy::refuse, "refuse"}, {MultiStemPolicy::separate, "separate"}, {MultiStemPolicy::merge, "merge"}}};

struct SurveyFormat {
  FieldSeparator separator = FieldSeparator::detect;
  std::map<SurveyColumn, std::string> units;  // a unit per column (stand.survey_units), e.g. dbh -> "mm"
  MultiStemPolicy multi_stem = MultiStemPolicy::refuse;
};

}  // namespace heliostand
