#pragma once
// Bad input is reported all at once, before any output is written, as lines of the form
//   stands/x.csv:14: column 'height': expected a number > 0, got "-3"
// and the executable exits with status 2 (see cli/main.cpp).
#include <stdexcept>
#include <string>
#include <vector>

namespace heliostand {

struct InputProblem {
  std::string file;
  int line = 0;        // 1-based; 0 when the problem is not tied to one line (e.g. unreadable file)
  std::string field;   // column name or TOML key path; empty when not tied to one field
  std::string reason;
  // Overrides the error's field kind for this problem ("column" in a survey problem merged into a
  // scenario error whose kind is "key"); empty: use the kind passed to format().
  std::string kind = {};

  // "FILE:LINE: column 'NAME': reason" (or "key 'a.b'" for TOML keys, chosen by `field_kind`).
  std::string format(const std::string& field_kind = "column") const;
};

class InputError : public std::runtime_error {
 public:
  explicit InputError(std::vector<InputProblem> problems, std::string field_kind = "column");
  const std::vector<InputProblem>& problems() const { return problems_; }
  const std::string& field_kind() const { return field_kind_; }

 private:
  std::vector<InputProblem> problems_;
  std::string field_kind_;
};

}  // namespace heliostand
