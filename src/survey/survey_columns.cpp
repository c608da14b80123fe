#include "survey/survey_columns.hpp"

#include <algorithm>
#include <array>
#include <cctype>

#include "core/trim_blanks.hpp"

namespace heliostand {

namespace {
using namespace std::string_view_literals;

constexpr std::array id_aliases{"id"sv, "tree_id"sv, "treeid"sv, "tree"sv, "tree_no"sv, "no"sv, "number"sv, "tag"sv};
constexpr std::array x_aliases{"x"sv, "pos_x"sv, "position_x"sv, "x_coord"sv, "gx"sv};
constexpr std::array y_aliases{"y"sv, "pos_y"sv, "position_y"sv, "y_coord"sv, "gy"sv};
constexpr std::array height_aliases{"height"sv, "h"sv, "ht"sv, "tree_height"sv};
constexpr std::array dbh_aliases{"dbh"sv, "d"sv, "d13"sv, "diameter"sv, "diam"sv, "bhd"sv};
constexpr std::array crown_radius_aliases{"crown_radius"sv, "cr"sv, "crown_r"sv};
constexpr std::array crown_diameter_aliases{"crown_diameter"sv, "cd"sv, "crown_d"sv, "crown_width"sv};
constexpr std::array crown_base_aliases{"crown_base"sv, "hcb"sv, "crown_base_height"sv, "live_crown_base"sv, "hlc"sv};
constexpr std::array age_aliases{"age"sv, "tree_age"sv};
constexpr std::array species_aliases{"species"sv, "sp"sv, "spp"sv};
constexpr std::array hollow_aliases{"hollow"sv, "hollows"sv, "cavity"sv, "cavities"sv};
constexpr std::array crown_ratio_aliases{"crown_ratio"sv, "crratio"sv, "cr_ratio"sv, "live_crown_ratio"sv, "lcr"sv};
constexpr std::array life_stage_aliases{"type"sv, "life_stage"sv};

using Q = Quantity;
const std::array<SurveyColumnInfo, survey_column_count> columns{{
    {SurveyColumn::id, "id", id_aliases, Q::none},
    {SurveyColumn::x, "x", x_aliases, Q::length},
    {SurveyColumn::y, "y", y_aliases, Q::length},
    {SurveyColumn::height, "height", height_aliases, Q::length},
    {SurveyColumn::dbh, "dbh", dbh_aliases, Q::stem_diameter},
    {SurveyColumn::crown_radius, "crown_radius", crown_radius_aliases, Q::length},
    {SurveyColumn::crown_diameter, "crown_diameter", crown_diameter_aliases, Q::length},
    {SurveyColumn::crown_base, "crown_base", crown_base_aliases, Q::length},
    {SurveyColumn::age, "age", age_aliases, Q::age},
    {SurveyColumn::species, "species", species_aliases, Q::none},
    {SurveyColumn::hollow, "hollow", hollow_aliases, Q::none},
    {SurveyColumn::crown_ratio, "crown_ratio", crown_ratio_aliases, Q::ratio},
    {SurveyColumn::life_stage, "life_stage", life_stage_aliases, Q::none},
}};

std::optional<SurveyColumn> column_with_alias(std::string_view name) {
  for (const auto& info : columns)
    if (std::find(info.aliases.begin(), info.aliases.end(), name) != info.aliases.end()) return info.column;
  return std::nullopt;
}
}  // namespace

std::span<const SurveyColumnInfo> survey_columns() { return columns; }

const SurveyColumnInfo& survey_column_info(SurveyColumn column) {
  return columns[static_cast<std::size_t>(column)];
}

std::string normalise_header_name(std::string_view cell) {
  std::string name;
  for (char c : trim_blanks(cell)) {
    if (c == ' ' || c == '-') c = '_';
    name += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return name;
}

std::optional<NamedColumn> survey_column_named(std::string_view header_cell) {
  const std::string name = normalise_header_name(header_cell);
  if (const auto column = column_with_alias(name)) return NamedColumn{*column, ""};
  if (const auto split = split_unit_suffix(name))
    if (const auto column = column_with_alias(split->name)) return NamedColumn{*column, split->unit};
  return std::nullopt;
}

std::optional<SurveyColumn> survey_column_by_name(std::string_view canonical_name) {
  for (const auto& info : columns)
    if (info.name == canonical_name) return info.column;
  return std::nullopt;
}

}  // namespace heliostand
