#pragma once
// The names a scenario key's string may take and the value each names (run.detail, run.vtk_compression, light.sky,
// hollow placement, stand.survey_separator, stand.multi_stem): one table a key, kept beside its type, from which the
// key's reader (scenario/toml_table_reader.hpp, TomlTableReader::choice), its refusal ("expected \"a\", \"b\" or
// \"c\"") and the value's own name all come. In core, so that the modules below the scenario keep their own tables.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace heliostand {

template <typename Value>
struct NamedChoice {
  Value value;
  std::string_view name;
};

template <typename Value, std::size_t N>
using NamedChoices = std::array<NamedChoice<Value>, N>;

// The name of `value` (the first entry's for a value the table lacks, which a complete table never does).
template <typename Value, std::size_t N>
constexpr std::string_view name_in(const NamedChoices<Value, N>& choices, Value value) {
  for (const NamedChoice<Value>& choice : choices)
    if (choice.value == value) return choice.name;
  return choices.front().name;
}

// The value `name` names; nullopt for a name the table lacks.
template <typename Value, std::size_t N>
constexpr std::optional<Value> choice_named(const NamedChoices<Value, N>& choices, std::string_view name) {
  for (const NamedChoice<Value>& choice : choices)
    if (choice.name == name) return choice.value;
  return std::nullopt;
}

// The names as a refusal lists them: "a", "b" or "c", each in double quotes.
template <typename Value, std::size_t N>
std::string quoted_names(const NamedChoices<Value, N>& choices) {
  std::string text;
  for (std::size_t i = 0; i < N; ++i) {
    if (i > 0) text += i + 1 == N ? " or " : ", ";
    text.append("\"").append(choices[i].name).append("\"");  // appended: gcc 12 warns (-Wrestrict) at "x" + string
  }
  return text;
}

}  // namespace heliostand
