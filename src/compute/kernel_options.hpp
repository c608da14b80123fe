#pragma once
// Build options of an OpenCL program. A constant that a kernel shares with C++ (a threshold both backends
// must apply alike) is passed here as -DNAME=value made from the C++ constant, so the C++ value is the only
// copy: cl/ files use the name and never #define it themselves.
#include <string>
#include <string_view>

namespace heliostand::compute {

class KernelOptions {
 public:
  KernelOptions& flag(std::string_view option);                // e.g. "-cl-std=CL1.2"
  KernelOptions& define(std::string_view name, int value);     // -DNAME=42
  KernelOptions& define(std::string_view name, double value);  // -DNAME=1e-05f (the kernel computes in float)
  const std::string& text() const { return text_; }

 private:
  KernelOptions& append(std::string_view option);
  std::string text_;
};

// An OpenCL C float literal that the kernel compiler reads as exactly static_cast<float>(value), e.g. "1e-05f".
// Throws std::invalid_argument for a value that is not finite in float.
std::string float_literal(double value);

}  // namespace heliostand::compute
