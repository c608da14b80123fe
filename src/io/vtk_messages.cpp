#include "io/vtk_messages.hpp"

#include <filesystem>
#include <string_view>

#include <spdlog/spdlog.h>
#include <vtkLogger.h>

namespace heliostand {
namespace {

spdlog::level::level_enum level_of(vtkLogger::Verbosity verbosity) {
  return verbosity <= vtkLogger::VERBOSITY_ERROR ? spdlog::level::err : spdlog::level::warn;
}

// One message: its first line at its level, with the VTK source file and line it came from; the rest (a pipeline
// request's dump after an error) at debug, where only -v shows it.
void log_message(void* /*user_data*/, const vtkLogger::Message& message) {
  std::string_view text = message.message ? message.message : "";
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.remove_suffix(1);
  const std::size_t line_end = text.find('\n');
  const std::string source = std::filesystem::path(message.filename ? message.filename : "").filename().string();
  spdlog::log(level_of(message.verbosity), "VTK ({}:{}): {}", source, message.line, text.substr(0, line_end));
  if (line_end != std::string_view::npos) spdlog::debug("VTK, continued: {}", text.substr(line_end + 1));
}

}  // namespace

void log_vtk_messages() {
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  constexpr const char* callback_id = "heliostand";
  vtkLogger::RemoveCallback(callback_id);  // a second call replaces the first, so each message is logged once
  vtkLogger::AddCallback(callback_id, &log_message, nullptr, vtkLogger::VERBOSITY_WARNING);
}

}  // namespace heliostand
