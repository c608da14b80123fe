#pragma once
// The columns a survey CSV may have, their canonical names and the aliases accepted in the header
// (docs/formats.md lists them). Header names are matched case-insensitively after trimming, with spaces
// and hyphens read as underscores ("Crown Base" = "crown-base" = "crown_base").
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace heliostand {

enum class SurveyColumn { id, x, y, height, dbh, crown_radius, crown_diameter, crown_base, age, species, hollow };

struct SurveyColumnInfo {
  SurveyColumn column;
  std::string_view name;                  // canonical name, used in messages about a missing column
  std::span<const std::string_view> aliases;
};

std::span<const SurveyColumnInfo> survey_columns();
const SurveyColumnInfo& survey_column_info(SurveyColumn column);

// The column a header cell names, or nothing for a column the survey does not use.
std::optional<SurveyColumn> survey_column_named(std::string_view header_cell);

// "Crown Base " -> "crown_base".
std::string normalise_header_name(std::string_view header_cell);

}  // namespace heliostand
