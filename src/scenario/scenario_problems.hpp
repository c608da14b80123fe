#pragma once
// Collects every problem found in a scenario, each with its key path and the line toml++ gives for it,
// so the user sees them all at once (docs/formats.md, "Errors").
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "core/input_error.hpp"

namespace heliostand {

class ScenarioProblems {
 public:
  explicit ScenarioProblems(std::string file) : file_(std::move(file)) {}

  const std::string& file() const { return file_; }
  void add(int line, std::string key_path, std::string reason) {
    problems_.push_back({file_, line, std::move(key_path), std::move(reason)});
  }
  void add(const toml::source_region& where, std::string key_path, std::string reason) {
    add(static_cast<int>(where.begin.line), std::move(key_path), std::move(reason));
  }
  // Problems of another file (the survey) keep their own file name and field kind.
  void merge(const InputError& error) {
    for (auto problem : error.problems()) {
      if (problem.kind.empty()) problem.kind = error.field_kind();
      problems_.push_back(std::move(problem));
    }
  }
  bool empty() const { return problems_.empty(); }
  std::size_t size() const { return problems_.size(); }
  void throw_if_any() const {
    if (!problems_.empty()) throw InputError(problems_, "key");
  }

 private:
  std::string file_;
  std::vector<InputProblem> problems_;
};

}  // namespace heliostand
