// A far-field cap the OpenCL device cannot hold, as a user meets it. `heliostand devices` lists what each device holds
// in one buffer; `grow` and `bench light --stand` refuse a scenario whose cap is beyond the chosen device's, under the
// scenario's key, before any output (light/far_field_buffers.hpp), and `check` says so. Before, such a run was
// established, wrote its tables' headers and failed at the first solve's clCreateBuffer (exit 1). Each test runs
// heliostand with POCL_MEMORY_LIMIT=1, under which PoCL reports 256 MiB a buffer (other OpenCL runtimes ignore it), and
// sets the cap one MB above what `heliostand devices` lists for the default device under the same environment.
// `bench light --far-field-table-mb` gives the cap on the command line; its refusal names the flag.
#include <gtest/gtest.h>

#include <regex>

#include "cli/cli_runner.hpp"
#include "compute/device_choice.hpp"
#include "tiny_stand_scenario.hpp"

namespace heliostand::testing {
namespace {

namespace fs = std::filesystem;

const std::string small_pocl = "POCL_MEMORY_LIMIT=1 ";

CliResult run_on_small_pocl(const std::string& arguments) {
  return run_command(small_pocl + heliostand_command() + " " + arguments);
}

// The default device's "N MB a buffer" in `heliostand devices`; -1 when the listing has none.
double default_device_buffer_mb() {
  const CliResult devices = run_on_small_pocl("devices");
  std::smatch match;
  const std::regex default_line(R"(\* opencl:[0-9]+ .*, ([0-9]+) MB a buffer\)  \[default\])");
  return std::regex_search(devices.output, match, default_line) ? std::stod(match[1]) : -1;
}

// stands/tiny with `far_field_table_mb = cap_mb`, in a fresh scratch folder `name`.
fs::path tiny_with_cap(const std::string& name, int cap_mb) {
  return write_tiny_stand_with_far_field_cap(scratch_folder(name), cap_mb);
}

TEST(FarFieldDeviceCli, GrowRefusesACapBeyondTheDeviceBeforeAnyOutput) {
  if (!compute::opencl_device_exists()) GTEST_SKIP() << "no OpenCL device";
  const double buffer_mb = default_device_buffer_mb();
  ASSERT_GT(buffer_mb, 0) << run_on_small_pocl("devices").output;
  const int cap = int(buffer_mb) + 1;
  const auto scenario = tiny_with_cap("far_field_device_grow", cap);
  const auto folder = scratch_folder("far_field_device_grow_out");
  const auto run = run_on_small_pocl("grow " + scenario.string() + " --out " + folder.string());
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_NE(run.output.find("scenario.toml: key 'light.far_field_table_mb': a far-field table of up to " +
                            std::to_string(cap) + " MB takes a buffer of up to"),
            std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("lower it to "), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(folder)) << "nothing may be written for a cap the device cannot hold";
}

// check reads such a scenario as good input (another device may hold it) and says that grow refuses it here.
TEST(FarFieldDeviceCli, CheckSaysGrowWouldRefuseTheCapHere) {
  if (!compute::opencl_device_exists()) GTEST_SKIP() << "no OpenCL device";
  const double buffer_mb = default_device_buffer_mb();
  ASSERT_GT(buffer_mb, 0) << run_on_small_pocl("devices").output;
  const int cap = int(buffer_mb) + 1;
  const auto beyond = run_on_small_pocl("check " + tiny_with_cap("far_field_device_check", cap).string());
  EXPECT_EQ(beyond.status, 0) << beyond.output;
  EXPECT_NE(beyond.output.find(", " + std::to_string(int(buffer_mb)) + " MB a buffer: grow refuses "
                               "light.far_field_table_mb = " + std::to_string(cap) + " MB here"),
            std::string::npos)
      << beyond.output;
  const auto within = run_on_small_pocl("check " + tiny_with_cap("far_field_device_check_within", cap - 1).string());
  EXPECT_EQ(within.status, 0) << within.output;
  EXPECT_NE(within.output.find(" MB a buffer\n"), std::string::npos) << within.output;
}

TEST(FarFieldDeviceCli, BenchLightRefusesSuchAStandBeforeAnyJson) {
  if (!compute::opencl_device_exists()) GTEST_SKIP() << "no OpenCL device";
  const double buffer_mb = default_device_buffer_mb();
  ASSERT_GT(buffer_mb, 0) << run_on_small_pocl("devices").output;
  const int cap = int(buffer_mb) + 1;
  const auto scenario = tiny_with_cap("far_field_device_bench", cap);
  const auto json = scratch_folder("far_field_device_bench_out") / "light.json";
  fs::create_directories(json.parent_path());
  const auto run = run_on_small_pocl("bench light --stand " + scenario.string() + " --device opencl -o " +
                                     json.string() + " -q");
  EXPECT_EQ(run.status, 2) << run.output;
  // the scenario's cap, not the default 512 MB (which such a device cannot hold either)
  EXPECT_NE(run.output.find("scenario.toml: key 'light.far_field_table_mb': a far-field table of up to " +
                            std::to_string(cap) + " MB takes a buffer of up to"),
            std::string::npos)
      << run.output;
  EXPECT_FALSE(fs::exists(json)) << "no JSON for a stand the device cannot light";
}

// `bench light --far-field-table-mb`: a cap the device cannot hold is refused under the flag, for the synthetic
// canopies and for a stand whose cap the flag replaced, before any solver runs; the cap the message advises is lit.
TEST(FarFieldDeviceCli, BenchLightRefusesAGivenCapBeyondTheDeviceUnderItsFlag) {
  if (!compute::opencl_device_exists()) GTEST_SKIP() << "no OpenCL device";
  const double buffer_mb = default_device_buffer_mb();
  ASSERT_GT(buffer_mb, 0) << run_on_small_pocl("devices").output;
  const auto folder = scratch_folder("far_field_device_bench_flag");
  fs::create_directories(folder);
  const auto json = folder / "light.json";
  const std::string synthetic = "bench light --balls 300 --subsample 20 --reference-culled-max 0 --device opencl -q";
  const std::string beyond = " --far-field-table-mb " + std::to_string(int(buffer_mb) + 1) + " -o " + json.string();

  const auto refused = run_on_small_pocl(synthetic + beyond);
  EXPECT_EQ(refused.status, 2) << refused.output;
  const std::string words = "--far-field-table-mb: a far-field table of up to " + std::to_string(int(buffer_mb) + 1) +
                            " MB takes a buffer of up to";
  EXPECT_NE(refused.output.find(words), std::string::npos) << refused.output;
  EXPECT_FALSE(fs::exists(json)) << "no JSON for a cap the device cannot hold";

  const auto stand = run_on_small_pocl("bench light --stand " + tiny_bench_stand.string() + " --device opencl -q" +
                                       beyond);
  EXPECT_EQ(stand.status, 2) << stand.output;
  EXPECT_NE(stand.output.find(words), std::string::npos) << "the flag gave the cap, not the scenario: " << stand.output;
  EXPECT_EQ(stand.output.find("key 'light.far_field_table_mb'"), std::string::npos) << stand.output;
  EXPECT_FALSE(fs::exists(json));

  std::smatch advice;
  ASSERT_TRUE(std::regex_search(refused.output, advice, std::regex("lower it to ([0-9]+) or less"))) << refused.output;
  const auto lit = run_on_small_pocl(synthetic + " --far-field-table-mb " + advice[1].str() + " -o " + json.string());
  ASSERT_EQ(lit.status, 0) << lit.output;
  const std::string written = read_text(json);
  EXPECT_NE(written.find("\"far_field_table_mb\": " + advice[1].str() + ".0"), std::string::npos) << written;
}

}  // namespace
}  // namespace heliostand::testing
