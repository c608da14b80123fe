#include "survey/survey_units.hpp"

#include <fmt/format.h>

#include <array>
#include <vector>

namespace heliostand {

namespace {
using namespace std::string_view_literals;

struct UnitEntry {
  Quantity quantity;
  std::string_view symbol;
  double factor;  // to the canonical unit
};

// International foot and inch (exact, 1959 agreement).
constexpr std::array units{
    UnitEntry{Quantity::length, "m", 1.0},           UnitEntry{Quantity::length, "cm", 0.01},
    UnitEntry{Quantity::length, "mm", 0.001},        UnitEntry{Quantity::length, "dm", 0.1},
    UnitEntry{Quantity::length, "ft", 0.3048},       UnitEntry{Quantity::length, "in", 0.0254},
    UnitEntry{Quantity::stem_diameter, "cm", 1.0},   UnitEntry{Quantity::stem_diameter, "mm", 0.1},
    UnitEntry{Quantity::stem_diameter, "m", 100.0},  UnitEntry{Quantity::stem_diameter, "dm", 10.0},
    UnitEntry{Quantity::stem_diameter, "in", 2.54},  UnitEntry{Quantity::stem_diameter, "ft", 30.48},
    UnitEntry{Quantity::age, "years", 1.0},          UnitEntry{Quantity::age, "year", 1.0},
    UnitEntry{Quantity::age, "yr", 1.0},             UnitEntry{Quantity::age, "y", 1.0},
    UnitEntry{Quantity::age, "a", 1.0},              UnitEntry{Quantity::ratio, "fraction", 1.0},
    UnitEntry{Quantity::ratio, "pct", 0.01},         UnitEntry{Quantity::ratio, "percent", 0.01},
    UnitEntry{Quantity::ratio, "%", 0.01},
};

bool is_unit_symbol(std::string_view word) {
  for (const auto& unit : units)
    if (unit.symbol == word) return true;
  return false;
}
}  // namespace

std::string_view canonical_unit(Quantity quantity) {
  switch (quantity) {
    case Quantity::length: return "m";
    case Quantity::stem_diameter: return "cm";
    case Quantity::age: return "years";
    case Quantity::ratio: return "fraction";
    case Quantity::none: break;
  }
  return "";
}

std::optional<double> unit_factor(Quantity quantity, std::string_view unit) {
  for (const auto& entry : units)
    if (entry.quantity == quantity && entry.symbol == unit) return entry.factor;
  return std::nullopt;
}

std::string accepted_units(Quantity quantity) {
  std::vector<std::string_view> symbols;
  for (const auto& entry : units)
    if (entry.quantity == quantity) symbols.push_back(entry.symbol);
  return symbols.empty() ? std::string("none (a column without unit)") : fmt::format("{}", fmt::join(symbols, ", "));
}

std::optional<NameWithUnit> split_unit_suffix(std::string_view name) {
  if (!name.empty() && (name.back() == ')' || name.back() == ']')) {
    const char open = name.back() == ')' ? '(' : '[';
    const auto at = name.rfind(open);
    if (at == std::string_view::npos || at == 0) return std::nullopt;
    std::string_view base = name.substr(0, at);
    while (!base.empty() && base.back() == '_') base.remove_suffix(1);
    std::string_view unit = name.substr(at + 1, name.size() - at - 2);
    while (!unit.empty() && unit.front() == '_') unit.remove_prefix(1);
    while (!unit.empty() && unit.back() == '_') unit.remove_suffix(1);
    if (base.empty() || unit.empty()) return std::nullopt;
    return NameWithUnit{std::string(base), std::string(unit)};
  }
  const auto at = name.rfind('_');
  if (at == std::string_view::npos || at == 0) return std::nullopt;
  const std::string_view unit = name.substr(at + 1);
  if (!is_unit_symbol(unit)) return std::nullopt;
  return NameWithUnit{std::string(name.substr(0, at)), std::string(unit)};
}

}  // namespace heliostand
