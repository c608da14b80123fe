#pragma once
// The columns a survey CSV may have, their canonical names and the aliases accepted in the header
// (docs/formats.md lists them): ours, and those of the tree lists foresters bring — iLand (`bhd`), SORTIE-ND
// tab tree maps (`X Y Species Type Diam Height`), FVS tree records (`Tree_ID`, `DBH`, `Ht`, `CrRatio`) and
// ForestGEO censuses (`tag`, `gx`, `gy`). Header names are matched case-insensitively after trimming, with
// spaces and hyphens read as underscores ("Crown Base" = "crown-base" = "crown_base"), and may end in a unit
// ("dbh_mm", "Height (ft)"; survey/survey_units.hpp).
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "survey/survey_units.hpp"

namespace heliostand {

enum class SurveyColumn {
  id, x, y, height, dbh, crown_radius, crown_diameter, crown_base, age, species, hollow,
  crown_ratio,  // live-crown length / height, the other way of giving the crown base (FVS CrRatio)
  life_stage    // SORTIE-ND's Type: seedling, sapling, adult, snag
};
constexpr std::size_t survey_column_count = 13;

struct SurveyColumnInfo {
  SurveyColumn column;
  std::string_view name;                  // canonical name, used in messages about a missing column
  std::span<const std::string_view> aliases;
  Quantity quantity;                      // what it measures: its canonical unit and the units it accepts
};

std::span<const SurveyColumnInfo> survey_columns();
const SurveyColumnInfo& survey_column_info(SurveyColumn column);

// The column a header cell names and the unit its name carries ("" when none), or nothing for a column the
// survey does not use. A whole name that is an alias wins over a unit suffix.
struct NamedColumn {
  SurveyColumn column;
  std::string unit;
};
std::optional<NamedColumn> survey_column_named(std::string_view header_cell);
// The column with this canonical name ("dbh", "crown_base"...): scenario stand.survey_units keys.
std::optional<SurveyColumn> survey_column_by_name(std::string_view canonical_name);

// "Crown Base " -> "crown_base".
std::string normalise_header_name(std::string_view header_cell);

}  // namespace heliostand
