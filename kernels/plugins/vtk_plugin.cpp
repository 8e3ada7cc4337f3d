// read_vtk (read.h) and decimate (decimate.h) forwarded to the VTK plugin (plugin.h), loaded on first use.
#include "kernels/base/plugin.h"
#include "kernels/io/read.h"
#include "kernels/plugins/vtk/vtk_table.h"
#include "kernels/print/decimate.h"

namespace selfsim {

namespace {

// Loaded once (a failed load is tried again on the next call).
const VtkTable& vtk() {
  static const VtkTable& table = *static_cast<const VtkTable*>(plugin_table(vtk_plugin, vtk_table_symbol));
  return table;
}

}  // namespace

namespace io {

Dataset read_vtk(const std::filesystem::path& file, bool unstructured) { return vtk().read_vtk(file, unstructured); }

}  // namespace io

namespace print {

Mesh decimate(const Mesh& m, double triangles, Progress& progress) { return vtk().decimate(m, triangles, progress); }

}  // namespace print

}  // namespace selfsim
