#pragma once
// Parameter structs (SpeciesParameters, LightParameters) are read from TOML tables whose keys are the
// struct's field names. A field list maps each key to its member and allowed range; one generic reader
// does the rest, so adding a parameter is one line here and one in the struct.
#include <span>
#include <string_view>
#include <variant>

#include "scenario/toml_table_reader.hpp"

namespace heliostand {

template <class Parameters>
struct ParameterField {
  std::string_view key;
  std::variant<double Parameters::*, int Parameters::*, bool Parameters::*> member;
  NumberRange range = {};  // ignored for booleans
};

// Overwrites the members whose keys the table holds; the others keep their (default) values.
template <class Parameters>
void read_parameter_fields(TomlTableReader& reader, std::span<const ParameterField<Parameters>> fields,
                           Parameters& parameters) {
  for (const auto& field : fields) {
    if (auto* d = std::get_if<double Parameters::*>(&field.member)) {
      if (auto value = reader.number(field.key, field.range)) parameters.*(*d) = *value;
    } else if (auto* i = std::get_if<int Parameters::*>(&field.member)) {
      if (auto value = reader.integer(field.key, field.range)) parameters.*(*i) = static_cast<int>(*value);
    } else if (auto* b = std::get_if<bool Parameters::*>(&field.member)) {
      if (auto value = reader.boolean(field.key)) parameters.*(*b) = *value;
    }
  }
}

}  // namespace heliostand
