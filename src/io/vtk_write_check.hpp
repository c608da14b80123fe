#pragma once
// Whether a VTK XML writer really wrote its file. VTK 9.1's XML writers return 1 from a write that failed (a full
// disk, a file size limit) and report it only in their error code, leaving a truncated file behind; every writer
// of ours reads that code through this check.
#include <filesystem>

class vtkXMLWriterBase;

namespace heliostand {

// Runs the writer (its file name and input already set) and throws OutputFolderError "cannot write FINAL_PATH:
// REASON" unless Write() returned 1 and the writer's error code is clear. REASON is the system's, where the code
// is an errno value (a failed stream), or "VTK: " and the name of vtkErrorCode's own code (OutOfDiskSpaceError
// where a piece failed). FINAL_PATH is the name the user will know the file by, which may differ from the
// writer's (a temporary).
void write_checked(vtkXMLWriterBase& writer, const std::filesystem::path& final_path);

}  // namespace heliostand
