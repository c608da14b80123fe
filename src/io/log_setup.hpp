#pragma once
// heliostand's log: one line a message on stderr, "level: message" (the level in colour on a terminal), so that
// stdout stays clean for machine-readable output (bench JSON, a check's summary). VTK's own warnings and errors
// go into it too (io/vtk_messages.hpp), instead of VTK's coloured, time-stamped dump.
#include <spdlog/common.h>

namespace heliostand {

// Makes that log spdlog's default logger, showing messages from `level` up, and routes VTK's messages into it.
// Called once, first thing, by the heliostand command and by the validation programs that write VTK.
void log_to_stderr(spdlog::level::level_enum level);

}  // namespace heliostand
