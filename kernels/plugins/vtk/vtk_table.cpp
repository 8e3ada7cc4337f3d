// The VTK plugin's one exported function: its table (vtk_table.h).
#include "kernels/plugins/vtk/vtk_table.h"

#include "kernels/io/read.h"
#include "kernels/print/decimate.h"

namespace {

const selfsim::VtkTable table{selfsim::io::read_vtk, selfsim::print::decimate};

}  // namespace

extern "C" __attribute__((visibility("default"))) const void* selfsim_vtk_table() { return &table; }
