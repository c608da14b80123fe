// Each kernel is compiled once per run, not once per launch. PoCL (the CPU OpenCL of Debian) compiles a kernel
// anew for every work-group size it is launched with and keeps one folder per size in its kernel cache
// (<kernel>/<size>-1-1-...). The roots are queried with a different number of root tips at every query, so
// while their launch left the group size to PoCL, three years of the tiny stand compiled the roots kernel 23
// times (7 of the run's 10 s on a 2-core machine; docs/performance.md "One compile per kernel").
#include <gtest/gtest.h>

#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "cli/cli_runner.hpp"
#include "compute/device_choice.hpp"

namespace heliostand::testing {
namespace {

namespace fs = std::filesystem;

// The work-group sizes each kernel was compiled for, from the cache folders <kernel>/<size>-...-/<kernel>.so.
std::map<std::string, std::set<std::string>> compiled_group_sizes(const fs::path& cache) {
  std::map<std::string, std::set<std::string>> sizes;
  for (const auto& entry : fs::recursive_directory_iterator(cache)) {
    if (entry.path().extension() != ".so") continue;
    const fs::path variant = entry.path().parent_path();
    const std::string kernel = variant.parent_path().filename().string();
    if (entry.path().stem() != kernel) continue;
    const std::string name = variant.filename().string();
    sizes[kernel].insert(name.substr(0, name.find('-')));
  }
  return sizes;
}

TEST(KernelCompiles, ThreeYearsOfTheTinyStandCompileEachKernelForOneGroupSize) {
  if (!compute::opencl_device_exists()) GTEST_SKIP() << "no OpenCL device";
  const fs::path folder = scratch_folder("kernel-compiles");
  fs::create_directories(folder);
  const fs::path cache = folder / "pocl-cache", json = folder / "bench.json";
  const CliResult cli = run_command("POCL_CACHE_DIR=" + cache.string() + " " + heliostand_command() +
                                    " bench stand " + tiny_bench_stand.string() +
                                    " --years 3 --device opencl -o " + json.string() + " -q");
  ASSERT_EQ(cli.status, 0) << cli.output;
  const std::string device = nlohmann::json::parse(read_text(json)).at("device");
  if (device.find("Portable Computing Language") == std::string::npos)
    GTEST_SKIP() << "the kernel cache read here is PoCL's; this device is " << device;
  ASSERT_TRUE(fs::is_directory(cache)) << "PoCL wrote no kernel cache at POCL_CACHE_DIR";
  const auto sizes = compiled_group_sizes(cache);
  // the roots kernel and the light kernels of the default solver all ran
  for (const char* kernel : {"root_contact_field", "light_culled_and_alone", "far_field_layer"})
    EXPECT_TRUE(sizes.contains(kernel)) << kernel << " not in the kernel cache";
  for (const auto& [kernel, compiled] : sizes) {
    std::string list;
    for (const auto& size : compiled) list += size + " ";
    EXPECT_EQ(compiled.size(), 1u) << kernel << " compiled for group sizes " << list;
  }
}

}  // namespace
}  // namespace heliostand::testing
