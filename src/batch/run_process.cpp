#include "batch/run_process.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include <chrono>
#include <cstring>
#include <fstream>

#include "core/seconds_since.hpp"

extern char** environ;

namespace heliostand {
namespace fs = std::filesystem;

fs::path own_executable() { return fs::read_symlink("/proc/self/exe"); }

namespace {

// The run's own "error: ..." lines (cli/report_errors.cpp prints every problem so), joined by "; ".
std::string error_lines(const fs::path& log_file) {
  std::ifstream log(log_file);
  std::string line, joined;
  while (std::getline(log, line)) {
    if (line.rfind("error:", 0) != 0) continue;
    if (!joined.empty()) joined += "; ";
    const std::size_t text = line.find_first_not_of(' ', 6);
    joined += text == std::string::npos ? std::string() : line.substr(text);
  }
  return joined;
}

// posix_spawn with its file actions released on every path.
class SpawnActions {
 public:
  SpawnActions() { posix_spawn_file_actions_init(&actions_); }
  ~SpawnActions() { posix_spawn_file_actions_destroy(&actions_); }
  SpawnActions(const SpawnActions&) = delete;
  SpawnActions& operator=(const SpawnActions&) = delete;
  posix_spawn_file_actions_t* get() { return &actions_; }

 private:
  posix_spawn_file_actions_t actions_;
};

}  // namespace

ProcessOutcome run_process(const fs::path& program, const std::vector<std::string>& arguments,
                           const fs::path& working_folder, const fs::path& log_file) {
  const auto start = std::chrono::steady_clock::now();
  ProcessOutcome outcome;
  SpawnActions actions;
  posix_spawn_file_actions_addchdir_np(actions.get(), working_folder.c_str());
  posix_spawn_file_actions_addopen(actions.get(), STDOUT_FILENO, log_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawn_file_actions_adddup2(actions.get(), STDOUT_FILENO, STDERR_FILENO);
  posix_spawn_file_actions_addopen(actions.get(), STDIN_FILENO, "/dev/null", O_RDONLY, 0);

  std::vector<char*> argv;
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  pid_t child = 0;
  const int spawn_error = posix_spawn(&child, program.c_str(), actions.get(), nullptr, argv.data(), environ);
  if (spawn_error != 0) {
    outcome.exit_status = 127;
    outcome.error = fmt::format("cannot start {}: {}", program.string(), std::strerror(spawn_error));
    return outcome;
  }
  int raw = 0;
  while (::waitpid(child, &raw, 0) < 0 && errno == EINTR) {
  }
  outcome.seconds = seconds_since(start);
  outcome.exit_status = WIFSIGNALED(raw) ? 128 + WTERMSIG(raw) : WEXITSTATUS(raw);
  outcome.error = failure_reason(outcome.exit_status, log_file);
  return outcome;
}

std::string failure_reason(int exit_status, const fs::path& log_file) {
  if (exit_status == 0) return {};
  // A shell's convention: above 128 is a signal (heliostand itself exits 0, 1 or 2).
  if (exit_status > 128) return fmt::format("killed by signal {} ({})", exit_status - 128, strsignal(exit_status - 128));
  std::string reason = error_lines(log_file);
  if (reason.empty()) reason = fmt::format("exit status {}", exit_status);
  return reason;
}

}  // namespace heliostand
