#pragma once

namespace heliostand::cli {

// Parses the command line and runs one subcommand. Returns the process exit status:
// 0 success, 1 runtime failure, 2 bad input (file, line, field and reason printed to stderr).
int run(int argc, char** argv);

}  // namespace heliostand::cli
