#include "survey/survey_columns.hpp"

#include <algorithm>
#include <array>
#include <cctype>

#include "survey/cell_text.hpp"

namespace heliostand {

namespace {
using namespace std::string_view_literals;

constexpr std::array id_aliases{"id"sv, "tree_id"sv, "tree"sv, "tree_no"sv, "no"sv, "number"sv};
constexpr std::array x_aliases{"x"sv, "x_m"sv, "pos_x"sv, "position_x"sv};
constexpr std::array y_aliases{"y"sv, "y_m"sv, "pos_y"sv, "position_y"sv};
constexpr std::array height_aliases{"height"sv, "height_m"sv, "h"sv, "h_m"sv, "ht"sv, "tree_height"sv};
constexpr std::array dbh_aliases{"dbh"sv, "dbh_cm"sv, "d"sv, "d_cm"sv, "d13"sv, "diameter"sv};
constexpr std::array crown_radius_aliases{"crown_radius"sv, "crown_radius_m"sv, "cr"sv, "crown_r"sv, "crown_r_m"sv};
constexpr std::array crown_diameter_aliases{"crown_diameter"sv, "crown_diameter_m"sv, "cd"sv, "crown_d"sv,
                                            "crown_width"sv, "crown_width_m"sv};
constexpr std::array crown_base_aliases{"crown_base"sv, "crown_base_m"sv, "hcb"sv, "crown_base_height"sv,
                                        "crown_base_height_m"sv, "live_crown_base"sv, "hlc"sv};
constexpr std::array age_aliases{"age"sv, "age_years"sv, "age_y"sv, "tree_age"sv};
constexpr std::array species_aliases{"species"sv, "sp"sv, "spp"sv};
constexpr std::array hollow_aliases{"hollow"sv, "hollows"sv, "cavity"sv, "cavities"sv};

const std::array<SurveyColumnInfo, 11> columns{{
    {SurveyColumn::id, "id", id_aliases},
    {SurveyColumn::x, "x", x_aliases},
    {SurveyColumn::y, "y", y_aliases},
    {SurveyColumn::height, "height", height_aliases},
    {SurveyColumn::dbh, "dbh", dbh_aliases},
    {SurveyColumn::crown_radius, "crown_radius", crown_radius_aliases},
    {SurveyColumn::crown_diameter, "crown_diameter", crown_diameter_aliases},
    {SurveyColumn::crown_base, "crown_base", crown_base_aliases},
    {SurveyColumn::age, "age", age_aliases},
    {SurveyColumn::species, "species", species_aliases},
    {SurveyColumn::hollow, "hollow", hollow_aliases},
}};
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

std::optional<SurveyColumn> survey_column_named(std::string_view header_cell) {
  const std::string name = normalise_header_name(header_cell);
  for (const auto& info : columns) {
    if (std::find(info.aliases.begin(), info.aliases.end(), name) != info.aliases.end()) return info.column;
  }
  return std::nullopt;
}

}  // namespace heliostand
