#pragma once
// A value a JSON report may not know: the value where there is one, null where there is none (the benchmarks' JSON
// and run.json: a processor's family, an unset environment variable).
#include <optional>

#include <nlohmann/json.hpp>

namespace heliostand {

template <class T>
nlohmann::ordered_json json_or_null(const std::optional<T>& value) {
  return value ? nlohmann::ordered_json(*value) : nlohmann::ordered_json();
}

}  // namespace heliostand
