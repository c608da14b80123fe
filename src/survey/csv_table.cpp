#include "survey/csv_table.hpp"

namespace heliostand {

namespace {

bool is_blank(const CsvRecord& record) {
  return record.fields.size() == 1 && record.fields.front().empty();
}

// Walks the text once; a small state machine over the characters of one record at a time.
class CsvScanner {
 public:
  CsvScanner(std::string_view text, const std::string& file, char separator)
      : text_(text), file_(file), separator_(separator) {
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") text_.remove_prefix(3);
  }

  CsvTable scan() {
    CsvTable table;
    while (pos_ < text_.size()) {
      CsvRecord record = next_record(table.problems);
      if (!is_blank(record)) table.records.push_back(std::move(record));
    }
    return table;
  }

 private:
  bool at_end() const { return pos_ >= text_.size(); }
  char peek() const { return text_[pos_]; }

  // Consumes a line break (LF or CRLF) if one is next; counts lines.
  bool take_line_break() {
    if (peek() == '\n') { ++pos_; ++line_; return true; }
    if (peek() == '\r' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '\n') { pos_ += 2; ++line_; return true; }
    return false;
  }

  CsvRecord next_record(std::vector<InputProblem>& problems) {
    CsvRecord record{line_, {}};
    bool broken = false;  // after a quoting error, skip to the end of the physical line
    while (true) {
      std::string field;
      if (!at_end() && peek() == '"') {
        broken = !read_quoted(field, record.line, problems) || broken;
      } else {
        broken = !read_plain(field, record.line, problems) || broken;
      }
      record.fields.push_back(std::move(field));
      if (at_end()) break;
      if (peek() == separator_) { ++pos_; continue; }
      if (take_line_break()) break;
      // Text after a closing quote: report once, then drop the rest of the line.
      if (!broken) problems.push_back({file_, record.line, "", "unexpected text after a closing quote"});
      broken = true;
      skip_line();
      break;
    }
    if (broken) record.fields.clear(), record.fields.push_back("");  // reported; do not validate it again
    return record;
  }

  bool read_plain(std::string& field, int record_line, std::vector<InputProblem>& problems) {
    bool ok = true;
    while (!at_end() && peek() != separator_ && peek() != '\n' &&
           !(peek() == '\r' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '\n')) {
      if (peek() == '"' && ok) {
        problems.push_back({file_, record_line, "", "a quote inside an unquoted field (quote the whole field and double the inner quotes)"});
        ok = false;
      }
      field += text_[pos_++];
    }
    return ok;
  }

  bool read_quoted(std::string& field, int record_line, std::vector<InputProblem>& problems) {
    ++pos_;  // opening quote
    while (!at_end()) {
      char c = text_[pos_];
      if (c == '"') {
        if (pos_ + 1 < text_.size() && text_[pos_ + 1] == '"') { field += '"'; pos_ += 2; continue; }
        ++pos_;  // closing quote
        return true;
      }
      if (c == '\n') ++line_;
      field += c;
      ++pos_;
    }
    problems.push_back({file_, record_line, "", "unterminated quoted field (a quote opened here is never closed)"});
    return false;
  }

  void skip_line() {
    while (!at_end() && !take_line_break()) ++pos_;
  }

  std::string_view text_;
  const std::string& file_;
  char separator_;
  std::size_t pos_ = 0;
  int line_ = 1;
};

}  // namespace

CsvTable parse_csv(std::string_view text, const std::string& file, char separator) {
  return CsvScanner(text, file, separator).scan();
}

}  // namespace heliostand
