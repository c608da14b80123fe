#include "survey/hollow_cell.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "core/trim_blanks.hpp"
#include "survey/strict_number.hpp"

namespace heliostand {
namespace {

std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    if (i == text.size() || text[i] == separator) {
      parts.push_back(text.substr(start, i - start));
      start = i + 1;
    }
  }
  return parts;
}

constexpr std::array<const char*, 4> field_names{"height_m", "azimuth_deg", "width_m", "wound_height_m"};

// One hollow, "1.4/135" or "1.4/135/0.08/0.15"; the error names the hollow (1-based) and the field.
std::variant<hollow::HollowSpec, std::string> parse_one(std::string_view text, std::size_t number) {
  const auto fields = split(text, '/');
  if (fields.size() != 2 && fields.size() != 4) {
    return fmt::format("hollow {}: expected HEIGHT_M/AZIMUTH_DEG or HEIGHT_M/AZIMUTH_DEG/WIDTH_M/WOUND_HEIGHT_M, "
                       "got \"{}\"",
                       number, text);
  }
  std::array<double, 4> values{};
  for (std::size_t i = 0; i < fields.size(); ++i) {
    const std::string_view field = trim_blanks(fields[i]);
    const auto value = parse_strict_number(std::string(field));
    if (!value || !std::isfinite(*value))
      return fmt::format("hollow {}: {}: expected a number, got \"{}\"", number, field_names[i], field);
    // Signs here, so a negative size is one clear message rather than every limit derived from it.
    const bool is_size = i != 1;
    if (is_size && (*value < 0 || (i >= 2 && *value == 0)))
      return fmt::format("hollow {}: {}: expected a number {} 0, got \"{}\"", number, field_names[i], i >= 2 ? ">" : ">=",
                         field);
    values[i] = *value;
  }
  hollow::HollowSpec spec;
  spec.height_m = values[0];
  spec.azimuth_deg = values[1];
  if (fields.size() == 4) {
    spec.width_m = values[2];
    spec.wound_height_m = values[3];
    // The cell has no room for the callus: scale the default roll to the entrance, so a small woodpecker hole
    // gets a thin roll rather than an error (r ≤ W/4 and I ≤ W/4 − r, seed 004).
    spec.callus_radius_m = std::clamp(spec.width_m / 8.0, hollow::seed_unit_m, hollow::HollowSpec{}.callus_radius_m);
    spec.bulge_m = std::clamp(spec.width_m / 4.0 - spec.callus_radius_m, 0.0, hollow::HollowSpec{}.bulge_m);
  }
  return spec;
}

}  // namespace

std::variant<std::vector<hollow::HollowSpec>, std::string> parse_hollow_cell(std::string_view cell) {
  std::vector<hollow::HollowSpec> hollows;
  cell = trim_blanks(cell);
  if (cell.empty()) return hollows;
  const auto entries = split(cell, ';');
  for (std::size_t i = 0; i < entries.size(); ++i) {
    auto one = parse_one(trim_blanks(entries[i]), i + 1);
    if (auto* reason = std::get_if<std::string>(&one)) return std::move(*reason);
    hollows.push_back(std::get<hollow::HollowSpec>(one));
  }
  return hollows;
}

}  // namespace heliostand
