// The functions of the VTK plugin (selfsim_vtk.so, plugin.h): VTK's own XML readers, behind read.h, and its
// quadric decimation, behind decimate.h. VTK's
// libraries take milliseconds to load and bind, which a run that reads no .vtp or .vtu should not pay.
#pragma once

#include <filesystem>

#include "kernels/base/progress.h"
#include "kernels/geom/mesh.h"
#include "kernels/io/dataset/dataset.h"

namespace selfsim {

struct VtkTable {
  io::Dataset (*read_vtk)(const std::filesystem::path&, bool);
  Mesh (*decimate)(const Mesh&, double, Progress&);
};

inline constexpr const char* vtk_plugin = "selfsim_vtk.so";
inline constexpr const char* vtk_table_symbol = "selfsim_vtk_table";

}  // namespace selfsim
