#pragma once
// Typed, range-checked reading of one TOML table. Every key the parser asks for is remembered, so that
// afterwards every other key can be reported as unknown (a misspelt key must not silently do nothing).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <string_view>

#include <toml++/toml.h>

#include "core/named_choice.hpp"
#include "scenario/scenario_problems.hpp"

namespace heliostand {

// An allowed interval, e.g. {0, {}, true} = "> 0"; both ends optional. Scenario keys give every number an upper
// limit with its reason (scenario/scenario_limits.hpp); `why` is quoted when a value is above it.
struct NumberRange {
  std::optional<double> min, max;
  bool min_exclusive = false, max_exclusive = false;
  bool overflow_guard = true;  // refuse magnitudes beyond largest_scenario_integer (not for seeds)
  std::string_view why = {};   // the fact behind `max`

  bool contains(double value) const;
  bool above_max(double value) const;
  std::string describe(std::string_view what) const;  // "a number > 0", "an integer in [1, 10]"
  // "expected a number in (0, 130], got 131 (the tallest ...)": the reason only for a value above the limit.
  std::string refusal(std::string_view what, double value, std::string_view value_text) const;
};

inline NumberRange positive() { return {0.0, std::nullopt, true, false}; }
inline NumberRange non_negative() { return {0.0, std::nullopt, false, false}; }
inline NumberRange at_least(double min) { return {min, std::nullopt, false, false}; }
inline NumberRange between(double min, double max) { return {min, max, false, false}; }
inline NumberRange any_number() { return {}; }
inline NumberRange any_seed() { return {0.0, std::nullopt, false, false, false}; }  // a random seed: any uint64

// No scenario number may exceed these in magnitude, whatever its own range: every quantity of the model is far
// smaller in its unit (heights in m, densities per ha, counts), and larger values overflow products in the
// growth equations (a site asymptote of 1e308 m). Random seeds are exempt (any_seed()).
constexpr double largest_scenario_number = 1e7;
constexpr std::int64_t largest_scenario_integer = 1'000'000;  // NumberRange::overflow_guard

// "a string", "an integer", ... for messages about wrong types.
std::string toml_type_phrase(const toml::node& node);

class TomlTableReader {
 public:
  // `path` is the key path of the table ("species.todomatsu", "thinning[2]"); `line` where it starts.
  TomlTableReader(const toml::table& table, std::string path, ScenarioProblems& problems);

  std::optional<double> number(std::string_view key, NumberRange range, bool required = false);
  std::optional<std::int64_t> integer(std::string_view key, NumberRange range, bool required = false);
  std::optional<bool> boolean(std::string_view key, bool required = false);
  std::optional<std::string> string(std::string_view key, bool required = false);
  // A string that must be one of `choices`' names: the value it names, else nullopt and a problem listing the names.
  template <typename Value, std::size_t N>
  std::optional<Value> choice(std::string_view key, const NamedChoices<Value, N>& choices) {
    const std::optional<std::string> text = string(key);
    if (!text) return std::nullopt;
    const std::optional<Value> value = choice_named(choices, *text);
    if (!value) {  // appended, not added: gcc 12 warns (-Wrestrict) at "literal" + string
      std::string reason = std::string("expected ").append(quoted_names(choices));
      problem(key, reason.append(", got \"").append(*text).append("\""));
    }
    return value;
  }
  // The raw node (or null), marked as known; for values the caller checks itself.
  const toml::node* node(std::string_view key);

  // Reports every key no accessor asked for. Call once, after reading.
  void report_unknown_keys();

  std::string key_path(std::string_view key) const;
  int line() const { return static_cast<int>(table_.source().begin.line); }
  int line_of(std::string_view key) const;
  const toml::table& table() const { return table_; }
  ScenarioProblems& problems() { return problems_; }
  void problem(std::string_view key, std::string reason);

 private:
  const toml::node* lookup(std::string_view key, bool required);

  const toml::table& table_;
  std::string path_;
  ScenarioProblems& problems_;
  std::set<std::string, std::less<>> known_;
};

}  // namespace heliostand
