// heliostand report RUN_DIR [RUN_DIR ...] [--out DIR] [--label NAME ...]: charts and a one-page summary of
// finished runs. The charts are drawn by src/report/heliostand_report.py with Debian's matplotlib; this command
// only starts it (python3, or $HELIOSTAND_PYTHON) with the same arguments and passes its exit status on, so the
// report can be made and tested without the simulator too.
#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "cli/commands.hpp"
#include "cli/path_checks.hpp"

extern char** environ;

namespace heliostand::cli {
namespace {

struct ReportArguments {
  std::vector<std::string> run_dirs;
  std::string out;
  std::vector<std::string> labels;
};

// Debian's python3-matplotlib installs for /usr/bin/python3; where several Python 3 are installed (pyenv, a
// virtual environment) the one first on PATH may lack it. HELIOSTAND_PYTHON names another to use.
std::string python_interpreter() {
  const char* chosen = std::getenv("HELIOSTAND_PYTHON");
  if (chosen != nullptr && *chosen != '\0') return chosen;
  std::error_code ec;
  return std::filesystem::exists("/usr/bin/python3", ec) ? "/usr/bin/python3" : "python3";
}

std::vector<std::string> script_command(const ReportArguments& arguments) {
  std::vector<std::string> command{python_interpreter(), HELIOSTAND_REPORT_SCRIPT};
  command.insert(command.end(), arguments.run_dirs.begin(), arguments.run_dirs.end());
  if (!arguments.out.empty()) command.insert(command.end(), {"--out", arguments.out});
  for (const auto& label : arguments.labels) command.insert(command.end(), {"--label", label});
  return command;
}

// Runs the command without a shell (folder names pass through unquoted) and waits for it.
int run_and_wait(const std::vector<std::string>& command) {
  std::vector<char*> argv;
  for (const auto& word : command) argv.push_back(const_cast<char*>(word.c_str()));
  argv.push_back(nullptr);
  std::fflush(stdout);  // the script writes to the same stdout and stderr
  std::fflush(stderr);
  pid_t child = 0;
  if (const int error = posix_spawnp(&child, argv[0], nullptr, nullptr, argv.data(), environ); error != 0) {
    fmt::print(stderr,
               "error: cannot run {} ({}): heliostand report draws its charts with Python 3 and matplotlib; install "
               "them with `apt-get install python3 python3-matplotlib`, or set HELIOSTAND_PYTHON to an interpreter "
               "that has matplotlib\n",
               command[0], std::strerror(error));
    return 1;
  }
  int wait_status = 0;
  while (waitpid(child, &wait_status, 0) < 0)
    if (errno != EINTR) return 1;
  if (WIFEXITED(wait_status)) return WEXITSTATUS(wait_status);
  fmt::print(stderr, "error: {} {} ended by signal {}\n", command[0], command[1], WTERMSIG(wait_status));
  return 1;
}

int report(const ReportArguments& arguments) {
  if (!std::filesystem::exists(HELIOSTAND_REPORT_SCRIPT)) {
    fmt::print(stderr, "error: the report script {} is missing (heliostand runs it from the source tree it was "
               "built from)\n", HELIOSTAND_REPORT_SCRIPT);
    return 1;
  }
  return run_and_wait(script_command(arguments));
}

}  // namespace

void add_report_command(CLI::App& app, int& status) {
  auto* command = app.add_subcommand(
      "report", "PNG charts and a one-page report.md of a run, or of several runs compared on the same axes");
  auto arguments = std::make_shared<ReportArguments>();
  command->add_option("run_dirs", arguments->run_dirs, "Run folder(s) written by `heliostand grow`")->required();
  command->add_option("-o,--out", arguments->out, "Report folder (default RUN_DIR/report; required with several runs)")
      ->check(path_check("folder"));
  // One value per --label, so that `--label thinned RUN_B` does not swallow the next run folder.
  command->add_option("--label", arguments->labels, "Legend name of a run: once per run, in the order of the folders")
      ->allow_extra_args(false);
  command->callback([arguments, &status] { status = report(*arguments); });
}

}  // namespace heliostand::cli
