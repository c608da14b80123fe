#pragma once
// Reads back a written .vtm file (a year of the stand's VTK output) for the tests to inspect.
#include <vtkMultiBlockDataSet.h>
#include <vtkSmartPointer.h>
#include <vtkXMLMultiBlockDataReader.h>

#include <filesystem>

namespace heliostand::testing {

inline vtkSmartPointer<vtkMultiBlockDataSet> read_multiblock(const std::filesystem::path& vtm) {
  auto reader = vtkSmartPointer<vtkXMLMultiBlockDataReader>::New();
  reader->SetFileName(vtm.string().c_str());
  reader->Update();
  return vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput());
}

}  // namespace heliostand::testing
