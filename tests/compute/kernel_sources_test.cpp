#include "compute/kernel_sources.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace heliostand::compute {

TEST(KernelSources, UnknownFileIsAnError) {
  EXPECT_THROW(kernel_source("no_such_kernel.cl"), std::runtime_error);
}

TEST(KernelSources, OverrideFolderIsReadAndIncludesAreInlined) {
  const auto dir = std::filesystem::temp_directory_path() / "heliostand_kernel_override_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "part.clh") << "#define ANSWER 42\n";
  std::ofstream(dir / "main.cl") << "#include \"part.clh\"\nkernel void k() {}\n";
  ::setenv("HELIOSTAND_KERNEL_DIR", dir.c_str(), 1);
  const std::string text = kernel_source("main.cl");
  ::unsetenv("HELIOSTAND_KERNEL_DIR");
  std::filesystem::remove_all(dir);
  EXPECT_NE(text.find("#define ANSWER 42"), std::string::npos);
  EXPECT_EQ(text.find("#include"), std::string::npos);
  EXPECT_NE(text.find("kernel void k()"), std::string::npos);
}

}  // namespace heliostand::compute
