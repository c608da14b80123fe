// Kernel build options: constants shared with C++ reach the kernel as -D options whose text reads back as the
// C++ value in float, exactly.
#include "compute/kernel_options.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <limits>
#include <stdexcept>

namespace heliostand::compute {
namespace {

TEST(KernelOptions, FloatLiteralsReadBackAsTheSameFloat) {
  for (double value : {1e-5, 0.1, 1.0 / 3.0, 1.0, 3.0, 123456789.0, 1e-30, -2.5, 0.0}) {
    const std::string text = float_literal(value);
    EXPECT_EQ(text.back(), 'f') << text;
    EXPECT_NE(text.find_first_of(".e"), std::string::npos) << text << ": OpenCL C reads 1f as no float literal";
    EXPECT_EQ(std::strtof(text.c_str(), nullptr), static_cast<float>(value)) << text;
  }
  EXPECT_EQ(float_literal(1e-5), "1e-05f");
  EXPECT_EQ(float_literal(2.0), "2.0f");
}

TEST(KernelOptions, AValueThatIsNoFiniteFloatIsAnError) {
  EXPECT_THROW(float_literal(1e300), std::invalid_argument);
  EXPECT_THROW(float_literal(std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
}

TEST(KernelOptions, FlagsAndDefinesInTheOrderGiven) {
  const auto options = KernelOptions().flag("-cl-std=CL1.2").define("SKY_BANDS", 16).define("FRACTION", 1e-5);
  EXPECT_EQ(options.text(), "-cl-std=CL1.2 -DSKY_BANDS=16 -DFRACTION=1e-05f");
  EXPECT_EQ(KernelOptions().text(), "");
}

}  // namespace
}  // namespace heliostand::compute
