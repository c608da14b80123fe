#pragma once
// VTK's own warnings and errors in heliostand's log. VTK 9.1 prints them to stderr through its own logger, one
// coloured, time-stamped line each, whatever -q or -v say; routed here they are log lines like any other
// ("warning: VTK (<source>.cxx:<line>): ..."), at the level the command line chose.

namespace heliostand {

// From now on, every VTK warning and error of the process goes to spdlog's default logger (errors as errors,
// warnings as warnings, the lines after a message's first as debug) and VTK prints nothing itself. Called once
// the log is set up (io/log_setup.hpp, which calls it); calling it again changes nothing.
void log_vtk_messages();

}  // namespace heliostand
