#include "io/vtk_write_check.hpp"

#include <fmt/format.h>
#include <vtkErrorCode.h>
#include <vtkXMLWriterBase.h>

#include "io/output_folder.hpp"

namespace heliostand {

void write_checked(vtkXMLWriterBase& writer, const std::filesystem::path& final_path) {
  const int write_result = writer.Write();
  const unsigned long code = writer.GetErrorCode();
  if (write_result == 1 && code == vtkErrorCode::NoError) return;
  if (code != vtkErrorCode::NoError && code < vtkErrorCode::FirstVTKErrorCode)
    throw cannot_write(final_path, static_cast<int>(code));
  throw OutputFolderError(fmt::format("cannot write {}: VTK: {}", final_path.string(),
                                      code != vtkErrorCode::NoError ? vtkErrorCode::GetStringFromErrorCode(code)
                                                                    : "the writer failed"));
}

}  // namespace heliostand
