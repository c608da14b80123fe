#include "core/input_error.hpp"

#include <fmt/format.h>

namespace heliostand {

std::string InputProblem::format(const std::string& field_kind) const {
  std::string where = file;
  if (line > 0) where += fmt::format(":{}", line);
  if (field.empty()) return fmt::format("{}: {}", where, reason);
  return fmt::format("{}: {} '{}': {}", where, kind.empty() ? field_kind : kind, field, reason);
}

namespace {
std::string join(const std::vector<InputProblem>& problems, const std::string& field_kind) {
  std::string text;
  for (const auto& problem : problems) {
    if (!text.empty()) text += '\n';
    text += problem.format(field_kind);
  }
  return text;
}
}  // namespace

InputError::InputError(std::vector<InputProblem> problems, std::string field_kind)
    : std::runtime_error(join(problems, field_kind)),
      problems_(std::move(problems)),
      field_kind_(std::move(field_kind)) {}

}  // namespace heliostand
