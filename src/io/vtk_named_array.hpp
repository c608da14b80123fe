#pragma once
// A VTK data array with its name (what ParaView lists and colours by), room reserved for `reserve` values.
#include <string>
#include <string_view>

#include <vtkSmartPointer.h>
#include <vtkType.h>

namespace heliostand {

template <typename Array>
vtkSmartPointer<Array> named_array(std::string_view name, vtkIdType reserve = 0) {
  auto array = vtkSmartPointer<Array>::New();
  array->SetName(std::string(name).c_str());
  array->Allocate(reserve);
  return array;
}

// The same, holding `size` values already, to be set by index (SetValue): for arrays whose length is known up front.
template <typename Array>
vtkSmartPointer<Array> sized_named_array(std::string_view name, vtkIdType size) {
  auto array = vtkSmartPointer<Array>::New();
  array->SetName(std::string(name).c_str());
  array->SetNumberOfTuples(size);
  return array;
}

}  // namespace heliostand
