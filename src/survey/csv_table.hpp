#pragma once
// A strict RFC-4180 reader that keeps the line number of every record, so that survey problems can be
// reported as FILE:LINE. Hand-written (about a hundred lines) because the Debian CSV library (libcsv)
// does not report line numbers and would be one more package to install.
#include <string>
#include <string_view>
#include <vector>

#include "core/input_error.hpp"

namespace heliostand {

struct CsvRecord {
  int line = 0;  // 1-based physical line where the record starts
  std::vector<std::string> fields;
};

struct CsvTable {
  std::vector<CsvRecord> records;      // the header is records[0] when present; blank lines are skipped
  std::vector<InputProblem> problems;  // quoting errors (record-level, no column)
};

// Splits `text` into records at `separator` (comma, semicolon or tab; survey/field_separator.hpp). Quoted
// fields may hold separators, doubled quotes and line breaks; a quote inside
// an unquoted field, text after a closing quote, or an unterminated quote is a problem. CRLF and a leading
// UTF-8 byte-order mark are accepted. `file` only labels problems.
CsvTable parse_csv(std::string_view text, const std::string& file, char separator = ',');

}  // namespace heliostand
