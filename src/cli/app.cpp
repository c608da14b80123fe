#include "cli/app.hpp"

#include <CLI/CLI.hpp>
#include <spdlog/common.h>

#include "cli/bench_command.hpp"
#include "cli/commands.hpp"
#include "cli/devices_command.hpp"
#include "cli/number_checks.hpp"
#include "core/parallel_for.hpp"
#include "io/log_setup.hpp"

namespace heliostand::cli {
namespace {

// -q shows warnings and errors, -v debug lines too.
void set_up_logging(int verbosity) {
  log_to_stderr(verbosity < 0 ? spdlog::level::warn : verbosity == 0 ? spdlog::level::info : spdlog::level::debug);
}

std::string command_line;

}  // namespace

const std::string& invoked_command_line() { return command_line; }

int run(int argc, char** argv) {
  for (int i = 0; i < argc; ++i) command_line += (i ? " " : "") + std::string(argv[i]);
  CLI::App app{"heliostand: grows a surveyed forest stand tree by tree and branch by branch"};
  app.set_version_flag("--version", std::string("heliostand ") + HELIOSTAND_VERSION);
  app.require_subcommand(1);
  app.fallthrough();  // global flags (-v, -q) may follow the subcommand
  int verbose = 0;
  bool quiet = false;
  app.add_flag("-v,--verbose", verbose, "More log output (debug)");
  app.add_flag("-q,--quiet", quiet, "Only warnings and errors");
  unsigned threads = 0;
  app.add_option("--threads", threads,
                 "Threads for the per-tree work (crowns, light response, root buds, the VTK crown envelopes); the "
                 "answers do not depend on it. Default: the cores. The OpenCL device chooses its own")
      ->check(whole_number_check());

  int status = 0;
  add_check_command(app, status);
  add_grow_command(app, status);
  add_kanamaru_command(app, status);
  add_report_command(app, status);
  add_batch_command(app, status);
  add_devices_command(app);
  add_bench_command(app);

  app.parse_complete_callback([&] {
    set_up_logging(quiet ? -1 : verbose);
    set_worker_threads(threads);
  });
  // Subcommands that do not report their own errors (devices, bench) throw out of parse().
  return report_errors([&] {
    try {
      app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
      const int code = app.exit(e);
      return code == 0 ? 0 : 2;  // usage errors are bad input
    }
    return status;
  });
}

}  // namespace heliostand::cli
