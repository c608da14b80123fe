#include "survey/survey_format.hpp"

namespace heliostand {

std::optional<MultiStemPolicy> multi_stem_policy_named(std::string_view name) {
  if (name == "refuse") return MultiStemPolicy::refuse;
  if (name == "separate") return MultiStemPolicy::separate;
  if (name == "merge") return MultiStemPolicy::merge;
  return std::nullopt;
}

}  // namespace heliostand
