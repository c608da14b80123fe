#pragma once
// Multi-stemmed trees: records whose stems stand within same_position_tolerance_m of each other.
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "survey/survey.hpp"

namespace heliostand {

constexpr double same_position_tolerance_m = 0.01;

// Groups of two or more records standing within the tolerance of each other (a chain of close stems is one
// group), each group in line order, the groups ordered by their first line.
std::vector<std::vector<std::size_t>> stems_sharing_a_position(const std::vector<SurveyRecord>& trees);

// One tree from the stems of a group (the first stem's id, line and position): DBH of the summed basal area
// (sqrt Σd², how inventories record a multi-stemmed tree), the tallest height, crown projection areas summed
// (radius sqrt Σr²), the lowest crown base, the greatest age, every hollow. The stems must be of one species:
// otherwise the reason why not.
struct MergedStems {
  std::optional<SurveyRecord> tree;
  std::string problem;
};
MergedStems merge_stems(std::span<const SurveyRecord* const> stems);

}  // namespace heliostand
