#include "io/vtk_write_check.hpp"

#include <fmt/format.h>
#include <vtkAlgorithm.h>
#include <vtkErrorCode.h>

#include "io/output_folder.hpp"

namespace heliostand {

void check_vtk_wrote(vtkAlgorithm& writer, int write_result, const std::filesystem::path& final_path) {
  const unsigned long code = writer.GetErrorCode();
  if (write_result == 1 && code == vtkErrorCode::NoError) return;
  if (code != vtkErrorCode::NoError && code < vtkErrorCode::FirstVTKErrorCode)
    throw cannot_write(final_path, static_cast<int>(code));
  throw OutputFolderError(fmt::format("cannot write {}: VTK: {}", final_path.string(),
                                      code != vtkErrorCode::NoError ? vtkErrorCode::GetStringFromErrorCode(code)
                                                                    : "the writer failed"));
}

}  // namespace heliostand
