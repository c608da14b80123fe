#pragma once
// The checks of the options that take a count or an amount. CLI11 2.1's PositiveNumber refuses 0 with "Value 0 not in
// range 0.000000 to 179769313486231570814527...000000" (its lower end is the smallest positive double printed to six
// places, its upper end every digit of the largest), and a word such as "abc" with the same sentence; its Range prints
// a range of doubles to six places ("Value 99 not in range 0.000000 to 4.000000") and lets "nan" through. These say
// what is expected and what was given, as the scenario's own checks do.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>

#include <fmt/format.h>

namespace heliostand {

// The parses the checks share: a count is digits and nothing else; an amount is a finite number that strtod reads
// whole.
inline bool is_digits(const std::string& value) {
  return !value.empty() && value.find_first_not_of("0123456789") == std::string::npos;
}
inline std::optional<double> finite_amount(const std::string& value) {
  if (value.empty()) return std::nullopt;
  char* end = nullptr;
  const double number = std::strtod(value.c_str(), &end);
  if (end != value.c_str() + value.size() || !std::isfinite(number)) return std::nullopt;
  return number;
}

// A count: a whole number >= `minimum` written in digits ("--years: a whole number >= 1 is expected, got 0"). Without
// it an unsigned option would store "-1" as 2^64 - 1 without a word.
inline CLI::Validator whole_number_check(unsigned long long minimum = 1) {
  return CLI::Validator(
      [minimum](std::string& value) -> std::string {
        const bool digits = is_digits(value);
        // Past 19 digits a number is above any minimum; whether it fits the option's type is CLI11's own check.
        const bool enough = digits && (value.size() > 19 || std::stoull(value) >= minimum);
        return enough ? std::string{}
                      : "a whole number >= " + std::to_string(minimum) + " is expected, got " + value;
      },
      "N >= " + std::to_string(minimum));
}

// An amount above 0 and at most `maximum` ("--cutoff: a number in (0, 1000] is expected, got 2000"), written as the
// scenario's check writes the same range.
inline CLI::Validator positive_amount_check(double maximum) {
  return CLI::Validator(
      [maximum](std::string& value) -> std::string {
        const std::optional<double> number = finite_amount(value);
        return number && *number > 0.0 && *number <= maximum
                   ? std::string{}
                   : fmt::format("a number in (0, {}] is expected, got {}", maximum, value);
      },
      fmt::format("X in (0, {}]", maximum));
}

// A count within limits ("--evaluations: a whole number in 1..1000 is expected, got 0").
inline CLI::Validator whole_number_check(unsigned long long minimum, unsigned long long maximum) {
  return CLI::Validator(
      [minimum, maximum](std::string& value) -> std::string {
        // At most 19 digits, so that stoull cannot overflow (past them a number is above any maximum).
        const bool digits = is_digits(value) && value.size() <= 19;
        const unsigned long long number = digits ? std::stoull(value) : 0;
        const bool within = digits && number >= minimum && number <= maximum;
        return within ? std::string{}
                      : fmt::format("a whole number in {}..{} is expected, got {}", minimum, maximum, value);
      },
      fmt::format("N in {}..{}", minimum, maximum));
}

// An amount within limits, both included ("--far-field-hand-over: a number in 0..4 is expected, got 99"), with the
// limits written as the scenario's check writes them, shortest first.
inline CLI::Validator amount_between_check(double minimum, double maximum) {
  return CLI::Validator(
      [minimum, maximum](std::string& value) -> std::string {
        const std::optional<double> number = finite_amount(value);
        return number && *number >= minimum && *number <= maximum
                   ? std::string{}
                   : fmt::format("a number in {}..{} is expected, got {}", minimum, maximum, value);
      },
      fmt::format("X in {}..{}", minimum, maximum));
}

}  // namespace heliostand
