#pragma once
// A `heliostand bench` command as the bench tests run it: its exit status and output, and the JSON it wrote with -o.
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/cli_runner.hpp"

namespace heliostand::testing {

struct BenchRun {
  CliResult cli;
  nlohmann::json json;  // read only when the command exited 0: a refused bench writes no JSON
};

// `heliostand bench ARGUMENTS -o FOLDER/FILE -q`, the folder made first.
inline BenchRun run_bench(const std::filesystem::path& folder, const std::string& file, const std::string& arguments) {
  std::filesystem::create_directories(folder);
  const std::filesystem::path json = folder / file;
  BenchRun bench;
  bench.cli = run_cli("bench " + arguments + " -o " + json.string() + " -q");
  if (bench.cli.status == 0) bench.json = nlohmann::json::parse(read_text(json));
  return bench;
}

}  // namespace heliostand::testing
