#pragma once
// The check every --seed option carries: a random seed is any whole number from 0 to 2^64 - 1, as run.seed in a
// scenario. CLI11 would otherwise store "-1" in an unsigned seed as 2^64 - 1 without a word.
#include <CLI/CLI.hpp>

#include <string>

#include "cli/number_checks.hpp"

namespace heliostand {

inline CLI::Validator seed_check() {
  return CLI::Validator(
      [](std::string& value) -> std::string {
        return is_digits(value) ? std::string{} : "a seed is a whole number >= 0, got " + value;
      },
      "SEED >= 0");
}

}  // namespace heliostand
