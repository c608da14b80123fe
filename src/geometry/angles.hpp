#pragma once
// Degrees live in files and parameters (as the papers give them); radians live inside the code.
#include <numbers>

namespace heliostand {

constexpr double pi = std::numbers::pi;
constexpr double radians(double degrees) { return degrees * pi / 180.0; }
constexpr double degrees(double radians) { return radians * 180.0 / pi; }

}  // namespace heliostand
