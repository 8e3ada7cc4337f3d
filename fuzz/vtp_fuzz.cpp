// Fuzz target: the .vtp reader (kernels/plugins/vtk/vtk_read.cpp behind kernels/io/vtk/vtk_header_check.cpp, VTK's
// vtkXMLPolyDataReader underneath), as `selfsim info FILE.vtp` and `selfsim diff` reach it. See read_fuzz.h.
#include <vtkObject.h>

#include "fuzz/read_fuzz.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  vtkObject::GlobalWarningDisplayOff();  // VTK's own messages about bad files: noise at thousands a second
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return selfsim::fuzz::read_one(data, size, ".vtp");
}
