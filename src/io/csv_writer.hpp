#pragma once
// A small RFC 4180 CSV writer: comma separator, "\n" line ends, fields quoted only when they must be
// (they contain a comma, a double quote, a line break, or leading/trailing spaces), quotes doubled.
// Numbers use a fixed number of decimals so tables diff cleanly between runs; NaN is an empty field.
// Once a header is written, every row must have as many fields: a row that does not is a writer's bug, and
// end_row() throws std::logic_error rather than let the columns of a table slide under the wrong names.
#include <initializer_list>
#include <ostream>
#include <span>
#include <string>
#include <string_view>

namespace heliostand {

// The field as it must appear in the file (quoted and escaped if needed).
std::string csv_field(std::string_view text);

// `value` with exactly `decimals` digits after the point ("-0.000" is written "0.000"); "" for NaN.
std::string csv_number(double value, int decimals);

class CsvWriter {
 public:
  explicit CsvWriter(std::ostream& out) : out_(out) {}

  void header(std::initializer_list<std::string_view> columns);
  void header(std::span<const std::string> columns);

  CsvWriter& text(std::string_view value);
  CsvWriter& integer(long long value);
  CsvWriter& number(double value, int decimals);
  void end_row();

 private:
  void separator();

  std::ostream& out_;
  bool row_started_ = false;
  std::size_t fields_in_row_ = 0;
  std::size_t header_fields_ = 0;  // 0 until a header is written: then no row is checked
};

}  // namespace heliostand
