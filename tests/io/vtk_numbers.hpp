#pragma once
// Every number a written or built VTK block holds, in order, so that two of them compare whole: a year written with
// two compressors, a block built on one thread and on several.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include <vtkAbstractArray.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace heliostand::testing {

// The points, each line's, polygon's and strip's point ids, then every point and cell array (a string array by its
// count).
inline void append_numbers(vtkPolyData& block, std::vector<double>& numbers) {
  const auto add_array = [&numbers](vtkAbstractArray* array) {
    numbers.push_back(static_cast<double>(array->GetNumberOfValues()));
    if (auto* data = vtkDataArray::SafeDownCast(array))
      for (vtkIdType i = 0; i < data->GetNumberOfValues(); ++i)
        numbers.push_back(data->GetComponent(i / data->GetNumberOfComponents(), int(i % data->GetNumberOfComponents())));
  };
  if (block.GetPoints()) add_array(block.GetPoints()->GetData());
  for (vtkCellArray* cells : {block.GetLines(), block.GetPolys(), block.GetStrips()})
    if (cells) add_array(cells->GetConnectivityArray());
  for (vtkFieldData* arrays :
       {static_cast<vtkFieldData*>(block.GetPointData()), static_cast<vtkFieldData*>(block.GetCellData())})
    for (int a = 0; a < arrays->GetNumberOfArrays(); ++a) add_array(arrays->GetAbstractArray(a));
}

inline std::vector<double> numbers_of(vtkPolyData& block) {
  std::vector<double> numbers;
  append_numbers(block, numbers);
  return numbers;
}

// Block by block (polydata blocks only).
inline std::vector<double> numbers_of(vtkMultiBlockDataSet& multiblock) {
  std::vector<double> numbers;
  for (unsigned b = 0; b < multiblock.GetNumberOfBlocks(); ++b)
    if (auto* block = vtkPolyData::SafeDownCast(multiblock.GetBlock(b))) append_numbers(*block, numbers);
  return numbers;
}

// The first index at which two lists of numbers differ, NaN equal to NaN (a value not defined, e.g. a tree's light
// before its first light field); -1 where they are the same.
inline long first_difference(const std::vector<double>& a, const std::vector<double>& b) {
  for (std::size_t i = 0; i < std::max(a.size(), b.size()); ++i) {
    if (i >= a.size() || i >= b.size()) return long(i);
    if (a[i] != b[i] && !(std::isnan(a[i]) && std::isnan(b[i]))) return long(i);
  }
  return -1;
}

}  // namespace heliostand::testing
