#include "scenario/toml_table_reader.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace heliostand {

bool NumberRange::contains(double value) const {
  if (min && (min_exclusive ? value <= *min : value < *min)) return false;
  return !above_max(value);
}

bool NumberRange::above_max(double value) const { return max && (max_exclusive ? value >= *max : value > *max); }

std::string NumberRange::refusal(std::string_view what, double value, std::string_view value_text) const {
  std::string text = fmt::format("expected {}, got {}", describe(what), value_text);
  if (above_max(value) && !why.empty()) text += fmt::format(" ({})", why);
  return text;
}

std::string NumberRange::describe(std::string_view what) const {
  if (min && max) {
    return fmt::format("{} in {}{:g}, {:g}{}", what, min_exclusive ? '(' : '[', *min, *max, max_exclusive ? ')' : ']');
  }
  if (min) return fmt::format("{} {} {:g}", what, min_exclusive ? ">" : ">=", *min);
  if (max) return fmt::format("{} {} {:g}", what, max_exclusive ? "<" : "<=", *max);
  return std::string(what);
}

std::string toml_type_phrase(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a floating-point number";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::array: return "an array";
    case toml::node_type::table: return "a table";
    default: return "a date/time";
  }
}

TomlTableReader::TomlTableReader(const toml::table& table, std::string path, ScenarioProblems& problems)
    : table_(table), path_(std::move(path)), problems_(problems) {}

std::string TomlTableReader::key_path(std::string_view key) const {
  return path_.empty() ? std::string(key) : fmt::format("{}.{}", path_, key);
}

int TomlTableReader::line_of(std::string_view key) const {
  const toml::node* found = table_.get(key);
  return found ? static_cast<int>(found->source().begin.line) : line();
}

void TomlTableReader::problem(std::string_view key, std::string reason) {
  problems_.add(line_of(key), key_path(key), std::move(reason));
}

const toml::node* TomlTableReader::lookup(std::string_view key, bool required) {
  known_.emplace(key);
  const toml::node* found = table_.get(key);
  if (!found && required) problems_.add(line(), key_path(key), "required key missing");
  return found;
}

const toml::node* TomlTableReader::node(std::string_view key) { return lookup(key, false); }

std::optional<double> TomlTableReader::number(std::string_view key, NumberRange range, bool required) {
  const toml::node* found = lookup(key, required);
  if (!found) return std::nullopt;
  std::optional<double> value;
  if (auto i = found->value_exact<std::int64_t>()) value = static_cast<double>(*i);
  if (auto f = found->value_exact<double>()) value = *f;
  if (!value) {
    problem(key, fmt::format("expected {}, got {}", range.describe("a number"), toml_type_phrase(*found)));
    return std::nullopt;
  }
  if (!std::isfinite(*value) || !range.contains(*value)) {
    // "{}" writes the shortest text that reads back as the value: one just above a limit does not show as the limit.
    const std::string_view what = std::isfinite(*value) ? "a number" : "a finite number";
    problem(key, range.refusal(what, *value, fmt::format("{}", *value)));
    return std::nullopt;
  }
  if (std::abs(*value) > largest_scenario_number) {
    problem(key, fmt::format("{:g} is beyond {:g}, larger than any quantity of the model in its unit (a slip, or a "
                             "value that would overflow the growth equations)",
                             *value, largest_scenario_number));
    return std::nullopt;
  }
  return value;
}

std::optional<std::int64_t> TomlTableReader::integer(std::string_view key, NumberRange range, bool required) {
  const toml::node* found = lookup(key, required);
  if (!found) return std::nullopt;
  auto value = found->value_exact<std::int64_t>();
  if (!value) {
    problem(key, fmt::format("expected {}, got {}", range.describe("an integer"), toml_type_phrase(*found)));
    return std::nullopt;
  }
  if (!range.contains(static_cast<double>(*value))) {
    problem(key, range.refusal("an integer", static_cast<double>(*value), std::to_string(*value)));
    return std::nullopt;
  }
  if (range.overflow_guard && std::abs(*value) > largest_scenario_integer) {
    problem(key, fmt::format("{} is beyond {}, larger than any count or age of the model (a slip, or a value that "
                             "would overflow)",
                             *value, largest_scenario_integer));
    return std::nullopt;
  }
  return value;
}

std::optional<bool> TomlTableReader::boolean(std::string_view key, bool required) {
  const toml::node* found = lookup(key, required);
  if (!found) return std::nullopt;
  auto value = found->value_exact<bool>();
  if (!value) problem(key, fmt::format("expected true or false, got {}", toml_type_phrase(*found)));
  return value;
}

std::optional<std::string> TomlTableReader::string(std::string_view key, bool required) {
  const toml::node* found = lookup(key, required);
  if (!found) return std::nullopt;
  auto value = found->value_exact<std::string>();
  if (!value) problem(key, fmt::format("expected a string, got {}", toml_type_phrase(*found)));
  return value;
}

void TomlTableReader::report_unknown_keys() {
  for (auto&& [key, value] : table_) {
    if (known_.count(key.str())) continue;
    problems_.add(key.source(), key_path(key.str()),
                  fmt::format("unknown key (known keys here: {})", fmt::join(known_, ", ")));
  }
}

}  // namespace heliostand
