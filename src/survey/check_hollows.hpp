#pragma once
// Whether the trunk of a surveyed tree can carry the hollows given for it (survey column or scenario
// [[hollow]]): each hollow against the tree's stem at the survey (height, crown base, species taper),
// and the hollows of one tree against each other. Problems are placed where each hollow was written.
#include <vector>

#include "architecture/species.hpp"
#include "core/input_error.hpp"
#include "survey/survey.hpp"

namespace heliostand {

std::vector<InputProblem> check_tree_hollows(const SurveyRecord& tree, const SpeciesParameters& species);

}  // namespace heliostand
