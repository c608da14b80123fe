#include <fmt/core.h>

#include <cstdio>
#include <exception>

#include "cli/commands.hpp"
#include "compute/failure_message.hpp"
#include "core/input_error.hpp"
#include "io/output_folder.hpp"

namespace heliostand::cli {

int report_errors(const std::function<int()>& body) {
  try {
    return body();
  } catch (const InputError& e) {
    for (const auto& problem : e.problems())
      fmt::print(stderr, "error: {}\n", problem.format(e.field_kind()));
    return 2;
  } catch (const OutputFolderError& e) {  // a refused --out folder is a usage mistake, not a failure
    fmt::print(stderr, "error: {}\n", e.what());
    return 2;
  } catch (const std::exception& e) {  // a failure while running (an OpenCL call, memory): said in words
    fmt::print(stderr, "error: {}\n", compute::failure_message(e));
    return 1;
  }
}

}  // namespace heliostand::cli
