#include "survey/field_separator.hpp"

#include <cstddef>

namespace heliostand {

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
  switch (separator) {
    case FieldSeparator::comma: return ',';
    case FieldSeparator::semicolon: return ';';
    case FieldSeparator::tab: return '\t';
    case FieldSeparator::detect: break;
  }
  return detect_field_separator(text);
}

}  // namespace heliostand
