#include "cli/app.hpp"

#include <CLI/CLI.hpp>

#include "cli/bench_command.hpp"
#include "cli/devices_command.hpp"

namespace heliostand::cli {

int run(int argc, char** argv) {
  CLI::App app{"heliostand: a forest stand simulator, tree by tree and branch by branch"};
  app.set_version_flag("--version", HELIOSTAND_VERSION);
  app.require_subcommand(1);
  add_devices_command(app);
  add_bench_command(app);
  CLI11_PARSE(app, argc, argv);
  return 0;
}

}  // namespace heliostand::cli
