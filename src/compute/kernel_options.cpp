#include "compute/kernel_options.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace heliostand::compute {

std::string float_literal(double value) {
  const float single = static_cast<float>(value);
  if (!std::isfinite(single))
    throw std::invalid_argument(fmt::format("kernel constant {} is not a finite float", value));
  // fmt writes the shortest text that reads back as the same float; C needs a '.' or an exponent before 'f'.
  std::string text = fmt::format("{}", single);
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return text + "f";
}

KernelOptions& KernelOptions::flag(std::string_view option) { return append(option); }

KernelOptions& KernelOptions::define(std::string_view name, int value) {
  return append(fmt::format("-D{}={}", name, value));
}

KernelOptions& KernelOptions::define(std::string_view name, double value) {
  return append(fmt::format("-D{}={}", name, float_literal(value)));
}

KernelOptions& KernelOptions::append(std::string_view option) {
  if (!text_.empty()) text_ += ' ';
  text_ += option;
  return *this;
}

}  // namespace heliostand::compute
