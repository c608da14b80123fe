#include "survey/field_separator.hpp"

#include <array>

namespace heliostand {

namespace {
struct NamedSeparator {
  FieldSeparator separator;
  std::string_view name;
  char character;
};
constexpr std::array named{NamedSeparator{FieldSeparator::detect, "auto", '\0'},
                           NamedSeparator{FieldSeparator::comma, "comma", ','},
                           NamedSeparator{FieldSeparator::semicolon, "semicolon", ';'},
                           NamedSeparator{FieldSeparator::tab, "tab", '\t'}};
}  // namespace

std::optional<FieldSeparator> field_separator_named(std::string_view name) {
  for (const auto& entry : named)
    if (entry.name == name) return entry.separator;
  return std::nullopt;
}

std::string_view field_separator_name(FieldSeparator separator) {
  return named[static_cast<std::size_t>(separator)].name;
}

char detect_field_separator(std::string_view text) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  std::size_t tabs = 0, semicolons = 0, commas = 0;
  bool quoted = false, seen_text = false;
  for (char c : text) {
    if (c == '"') quoted = !quoted;
    if (quoted) continue;
    if (c == '\n') {
      if (seen_text) break;
      continue;
    }
    if (c != ' ' && c != '\r') seen_text = true;
    tabs += c == '\t';
    semicolons += c == ';';
    commas += c == ',';
  }
  if (tabs > 0 && tabs >= semicolons && tabs >= commas) return '\t';
  if (semicolons > 0 && semicolons >= commas) return ';';
  return ',';
}

char separator_char(FieldSeparator separator, std::string_view text) {
  return separator == FieldSeparator::detect ? detect_field_separator(text)
                                             : named[static_cast<std::size_t>(separator)].character;
}

}  // namespace heliostand
