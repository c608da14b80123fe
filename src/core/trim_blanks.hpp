#pragma once
// Text read without the blanks around it: survey cells and header names (spreadsheets pad cells), and the keys and
// values of /proc/cpuinfo (tab-aligned).
#include <string_view>

namespace heliostand {

// `text` without leading and trailing spaces and tabs.
inline std::string_view trim_blanks(std::string_view text) {
  auto is_blank = [](char c) { return c == ' ' || c == '\t'; };
  while (!text.empty() && is_blank(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_blank(text.back())) text.remove_suffix(1);
  return text;
}

}  // namespace heliostand
