// heliostand: the command-line entry point. Subcommands live in cli/*.cpp.
#include "cli/app.hpp"

int main(int argc, char** argv) { return heliostand::cli::run(argc, argv); }
