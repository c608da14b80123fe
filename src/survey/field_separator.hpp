#pragma once
// The character between the fields of a survey file. Inventory exports differ by country and tool: comma
// (RFC 4180), semicolon (European spreadsheets, where the comma is the decimal mark) and tab (SORTIE-ND tree
// maps, iLand tree lists). The reader detects it from the header line unless the scenario names it.
#include <string_view>

#include "core/named_choice.hpp"

namespace heliostand {

enum class FieldSeparator { detect, comma, semicolon, tab };

// The names of the scenario key stand.survey_separator.
inline constexpr NamedChoices<FieldSeparator, 4> field_separator_names{{{FieldSeparator::detect, "auto"},
                                                                        {FieldSeparator::comma, "comma"},
                                                                        {FieldSeparator::semicolon, "semicolon"},
                                                                        {FieldSeparator::tab, "tab"}}};

// The separator of the first non-blank line: the most frequent of tab, semicolon and comma outside quotes
// (comma when none occurs, a one-column file). Ties go tab, then semicolon, then comma: a header cell rarely
// holds a tab or a semicolon, while "DBH, cm" style names do hold commas.
char detect_field_separator(std::string_view text);

// The character `separator` stands for; detect looks at `text`.
char separator_char(FieldSeparator separator, std::string_view text);

}  // namespace heliostand
