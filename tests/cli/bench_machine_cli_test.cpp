// Both benchmarks' JSON, and a run's run.json, name the machine their seconds are of: the hardware threads and the
// processor (model name, CPU family and model, vector extensions), so figures from two machines that lscpu calls
// alike are not compared, and the allocator's settings (GLIBC_TUNABLES, the kernel's transparent-huge-page mode),
// which move one binary's hectare by a tenth on some machines.
#include <gtest/gtest.h>

#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "cli/cli_runner.hpp"
#include "core/page_settings.hpp"
#include "core/processor.hpp"

namespace heliostand::testing {
namespace {

namespace fs = std::filesystem;

void expect_this_machine(const nlohmann::json& json) {
  EXPECT_EQ(json.at("hardware_threads").get<unsigned>(), std::thread::hardware_concurrency());
  EXPECT_EQ(json.at("processor"), nlohmann::json(processor_json(this_processor())));
  EXPECT_FALSE(json.at("processor").at("vector_extensions").empty()) << json.at("processor").dump();
}

// The settings the benchmark ran under: the child inherits this process's environment.
void expect_these_page_settings(const nlohmann::json& json) {
  EXPECT_EQ(json.at("pages"), nlohmann::json(page_settings_json(this_process_page_settings())));
}

// heliostand with GLIBC_TUNABLES set for its run alone (glibc reads it when the process starts).
CliResult run_cli_with_tunables(const std::string& tunables, const std::string& arguments) {
  return run_command("GLIBC_TUNABLES=" + tunables + " " + heliostand_command() + " " + arguments);
}

}  // namespace

TEST(BenchMachineCli, TheLightBenchmarkNamesThisProcessor) {
  const fs::path folder = scratch_folder("bench-machine-light");
  fs::create_directories(folder);
  const fs::path file = folder / "light.json";
  const CliResult cli = run_cli(quick_reference_light_bench + " -q -o " + file.string());
  ASSERT_EQ(cli.status, 0) << cli.output;
  expect_this_machine(nlohmann::json::parse(read_text(file)));
  expect_these_page_settings(nlohmann::json::parse(read_text(file)));
}

// A variable set for the benchmark alone is the one it records (glibc reads it at the start; so does the JSON).
TEST(BenchMachineCli, TheLightBenchmarkRecordsTheGlibcTunablesItRanWith) {
  const fs::path folder = scratch_folder("bench-machine-tunables");
  fs::create_directories(folder);
  const fs::path file = folder / "light.json";
  const std::string tunables = "glibc.malloc.hugetlb=1";
  const CliResult cli = run_cli_with_tunables(tunables, quick_reference_light_bench + " -q -o " + file.string());
  ASSERT_EQ(cli.status, 0) << cli.output;
  EXPECT_EQ(nlohmann::json::parse(read_text(file)).at("pages").at("glibc_tunables"), tunables);
}

TEST(BenchMachineCli, TheStandBenchmarkNamesThisProcessor) {
  const fs::path folder = scratch_folder("bench-machine-stand");
  fs::create_directories(folder);
  const fs::path file = folder / "stand.json";
  const CliResult cli = run_cli("bench stand " + tiny_bench_stand.string() +
                                " --years 1 --device reference -q -o " + file.string());
  ASSERT_EQ(cli.status, 0) << cli.output;
  expect_this_machine(nlohmann::json::parse(read_text(file)));
  expect_these_page_settings(nlohmann::json::parse(read_text(file)));
}

// run.json names the machine of the session that finished the run (docs/formats.md "run.json").
TEST(BenchMachineCli, TheRunManifestNamesTheMachineThatFinishedTheRun) {
  const fs::path folder = scratch_folder("bench-machine-grow");
  const CliResult cli =
      run_cli("grow " + tiny_bench_stand.string() + " --years 1 --device reference -q --out " + folder.string());
  ASSERT_EQ(cli.status, 0) << cli.output;
  const nlohmann::json finished_on = nlohmann::json::parse(read_text(folder / "run.json")).at("finished_on");
  expect_this_machine(finished_on);
  expect_these_page_settings(finished_on);
}

// A grow run with the variable docs/user-guide.md suggests for long runs records it beside its seconds.
TEST(BenchMachineCli, TheRunManifestRecordsTheGlibcTunablesTheRunFinishedWith) {
  const fs::path folder = scratch_folder("bench-machine-grow-tunables");
  const std::string tunables = "glibc.malloc.hugetlb=1";
  const CliResult cli = run_cli_with_tunables(
      tunables, "grow " + tiny_bench_stand.string() + " --years 1 --device reference -q --out " + folder.string());
  ASSERT_EQ(cli.status, 0) << cli.output;
  EXPECT_EQ(nlohmann::json::parse(read_text(folder / "run.json")).at("finished_on").at("pages").at("glibc_tunables"),
            tunables);
}

}  // namespace heliostand::testing
