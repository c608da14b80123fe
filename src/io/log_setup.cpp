#include "io/log_setup.hpp"

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "io/vtk_messages.hpp"

namespace heliostand {

void log_to_stderr(spdlog::level::level_enum level) {
  spdlog::drop("heliostand");  // a second call replaces the first logger rather than failing on its name
  auto logger = spdlog::stderr_color_mt("heliostand");
  logger->set_pattern("%^%l%$: %v");
  logger->set_level(level);
  spdlog::set_default_logger(logger);
  log_vtk_messages();
}

}  // namespace heliostand
