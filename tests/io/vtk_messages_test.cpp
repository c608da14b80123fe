// VTK's own warnings and errors reach heliostand's log (io/vtk_messages.hpp) at the level they deserve, and VTK
// prints nothing to stderr itself.

#include "io/vtk_messages.hpp"

#include <gtest/gtest.h>

#include <string>

#include <vtkObject.h>

#include "io/captured_log.hpp"

namespace heliostand {
namespace {

class VtkMessages : public ::testing::Test {
 protected:
  VtkMessages() { log_vtk_messages(); }  // a second time, after CapturedLog's: still one line a message
  testing::CapturedLog log_;
};

std::string vtk_source(int line) { return "(vtk_messages_test.cpp:" + std::to_string(line) + ")"; }

TEST_F(VtkMessages, AWarningIsALogWarningOnceAndVtkPrintsNothing) {
  ::testing::internal::CaptureStderr();
  const int line = __LINE__ + 1;
  vtkGenericWarningMacro("the mesh is suspect");
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  EXPECT_EQ(log_.text(), "warning: VTK " + vtk_source(line) + ": the mesh is suspect\n");
}

TEST_F(VtkMessages, AnErrorIsALogErrorAndItsFurtherLinesAreDebug) {
  ::testing::internal::CaptureStderr();
  const int line = __LINE__ + 1;
  vtkErrorWithObjectMacro(nullptr, "cannot open the file\n  Request: REQUEST_DATA\n");
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  EXPECT_EQ(log_.text(), "error: VTK " + vtk_source(line) + ": (nullptr): cannot open the file\n"
                         "debug: VTK, continued:   Request: REQUEST_DATA\n");
}

}  // namespace
}  // namespace heliostand
