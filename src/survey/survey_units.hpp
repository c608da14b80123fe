#pragma once
// Units of survey columns. Inventories record DBH in cm, mm, m or inches and heights in m or feet; the
// header may say which (`dbh_mm`, `height_ft`, `DBH (cm)`, `d [m]`), or the scenario may (stand.survey_units).
// Every value is converted on reading to the column's canonical unit: metres for positions, heights and crown
// sizes, centimetres for DBH, years for age, a fraction for the crown ratio.
#include <optional>
#include <string>
#include <string_view>

namespace heliostand {

// What a survey column measures, which fixes its canonical unit and the units it accepts.
enum class Quantity { none, length, stem_diameter, age, ratio };

std::string_view canonical_unit(Quantity quantity);  // "m", "cm", "years", "fraction"; "" for none

// The factor taking a value in `unit` to the canonical unit of `quantity`; nothing if the unit does not
// measure that quantity (e.g. "%" for a height).
std::optional<double> unit_factor(Quantity quantity, std::string_view unit);

// The units `quantity` accepts, for messages: "m, cm, mm, dm, ft, in".
std::string accepted_units(Quantity quantity);

// A normalised header name split into the column name and a unit suffix: "dbh_mm" -> {dbh, mm},
// "dbh_(cm)" / "dbh_[cm]" / "dbh(cm)" -> {dbh, cm}. A trailing "_word" is a unit only when `word` is a
// unit of some quantity ("tree_id" stays whole); nothing when the name carries no unit.
struct NameWithUnit {
  std::string name;
  std::string unit;
};
std::optional<NameWithUnit> split_unit_suffix(std::string_view normalised_name);

}  // namespace heliostand
