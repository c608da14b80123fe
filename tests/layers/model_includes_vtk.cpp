// Must NOT compile (CTest layers.model_cannot_include_vtk): the models link no VTK, so its headers are not on their
// include path; drawing a tree is io/'s business.
#include <vtkPolyData.h>
