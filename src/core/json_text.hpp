#pragma once
// The text of a JSON report (the benchmarks' JSON, run.json): indented by two, ending in a newline, and a string
// that is not UTF-8 (a path in a legacy encoding) written with its invalid bytes replaced by U+FFFD rather than
// refused. Refused, the report was lost after the whole run it describes (`bench stand`, before 2026-12-02).
#include <string>

#include <nlohmann/json.hpp>

namespace heliostand {

inline std::string json_text(const nlohmann::ordered_json& json) {
  return json.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

}  // namespace heliostand
