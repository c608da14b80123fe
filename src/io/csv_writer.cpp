#include "io/csv_writer.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace heliostand {

std::string csv_field(std::string_view text) {
  const bool needs_quotes = text.find_first_of(",\"\r\n") != std::string_view::npos ||
                            (!text.empty() && (text.front() == ' ' || text.back() == ' '));
  if (!needs_quotes) return std::string(text);
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';  // RFC 4180: a quote inside a quoted field is doubled
    quoted += c;
  }
  quoted += '"';
  return quoted;
}

std::string csv_number(double value, int decimals) {
  if (std::isnan(value)) return {};
  std::string s = fmt::format("{:.{}f}", value, decimals);
  // A tiny negative value rounds to "-0.00"; a signed zero in a table only confuses readers.
  if (s.front() == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

void CsvWriter::header(std::initializer_list<std::string_view> columns) {
  for (std::string_view column : columns) text(column);
  header_fields_ = fields_in_row_;
  end_row();
}

void CsvWriter::header(std::span<const std::string> columns) {
  for (const std::string& column : columns) text(column);
  header_fields_ = fields_in_row_;
  end_row();
}

void CsvWriter::separator() {
  if (row_started_) out_ << ',';
  row_started_ = true;
  ++fields_in_row_;
}

CsvWriter& CsvWriter::text(std::string_view value) {
  separator();
  out_ << csv_field(value);
  return *this;
}

CsvWriter& CsvWriter::integer(long long value) {
  separator();
  out_ << value;
  return *this;
}

CsvWriter& CsvWriter::number(double value, int decimals) {
  separator();
  out_ << csv_number(value, decimals);
  return *this;
}

void CsvWriter::end_row() {
  if (header_fields_ > 0 && fields_in_row_ != header_fields_)
    throw std::logic_error(fmt::format("csv row of {} fields under a header of {}", fields_in_row_, header_fields_));
  out_ << '\n';
  row_started_ = false;
  fields_in_row_ = 0;
}

}  // namespace heliostand
