#include "core/page_settings.hpp"

#include <cstdlib>
#include <fstream>
#include <istream>

#include <nlohmann/json.hpp>

#include "core/json_or_null.hpp"

namespace heliostand {

std::optional<std::string> chosen_transparent_huge_pages(std::istream& enabled) {
  std::string word;
  while (enabled >> word)
    if (word.size() > 2 && word.front() == '[' && word.back() == ']') return word.substr(1, word.size() - 2);
  return std::nullopt;
}

PageSettings this_process_page_settings() {
  PageSettings settings;
  // glibc reads the variable once, at the process's start; the environment still holds what it read.
  if (const char* tunables = std::getenv("GLIBC_TUNABLES"); tunables != nullptr) settings.glibc_tunables = tunables;
  if (std::ifstream enabled("/sys/kernel/mm/transparent_hugepage/enabled"); enabled)
    settings.transparent_huge_pages = chosen_transparent_huge_pages(enabled);
  return settings;
}

nlohmann::ordered_json page_settings_json(const PageSettings& settings) {
  nlohmann::ordered_json json;
  json["glibc_tunables"] = json_or_null(settings.glibc_tunables);
  json["transparent_huge_pages"] = json_or_null(settings.transparent_huge_pages);
  return json;
}

}  // namespace heliostand
