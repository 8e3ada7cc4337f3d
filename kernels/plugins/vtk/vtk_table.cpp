// The VTK plugin's one exported function: its table (vtk_table.h).
#include "kernels/plugins/vtk/vtk_table.h"

#include "kernels/io/read.h"

namespace {

const selfsim::VtkTable table{selfsim::io::read_vtk};

}  // namespace

extern "C" __attribute__((visibility("default"))) const void* selfsim_vtk_table() { return &table; }
