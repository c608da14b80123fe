#include "compute/kernel_sources.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "scoped_environment.hpp"

namespace heliostand::compute {

TEST(KernelSources, UnknownFileIsAnError) {
  EXPECT_THROW(kernel_source("no_such_kernel.cl"), std::runtime_error);
}

TEST(KernelSources, OverrideFolderIsReadAndIncludesAreInlined) {
  const auto dir = std::filesystem::temp_directory_path() / "heliostand_kernel_override_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "part.clh") << "#define ANSWER 42\n";
  std::ofstream(dir / "main.cl") << "#include \"part.clh\"\nkernel void k() {}\n";
  const std::string text = [&] {
    const testing::ScopedEnvironment kernel_dir("HELIOSTAND_KERNEL_DIR", dir.string());
    return kernel_source("main.cl");
  }();
  std::filesystem::remove_all(dir);
  EXPECT_NE(text.find("#define ANSWER 42"), std::string::npos);
  EXPECT_EQ(text.find("#include"), std::string::npos);
  EXPECT_NE(text.find("kernel void k()"), std::string::npos);
}

}  // namespace heliostand::compute
