#pragma once
// Each subcommand registers itself (devices and bench: cli/devices_command.hpp, cli/bench_command.hpp) on the application; its callback stores the exit status in `status`
// (0 success, 1 runtime failure, 2 bad input).
#include <functional>
#include <string>

#include <CLI/App.hpp>

namespace heliostand::cli {

void add_check_command(CLI::App& app, int& status);
void add_grow_command(CLI::App& app, int& status);
void add_kanamaru_command(CLI::App& app, int& status);
void add_report_command(CLI::App& app, int& status);
void add_batch_command(CLI::App& app, int& status);

// The command line as typed (argv joined by spaces), for run.json.
const std::string& invoked_command_line();

// Runs `body`, turning exceptions into messages on stderr and an exit status:
// InputError → every problem on its own line, status 2; a refused output folder → status 2;
// anything else → status 1.
int report_errors(const std::function<int()>& body);

}  // namespace heliostand::cli
