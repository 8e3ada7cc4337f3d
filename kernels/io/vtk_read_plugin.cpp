// read_vtk (read.h) forwarded to the VTK plugin (plugin.h), loaded on first use.
#include "kernels/geom/plugin.h"
#include "kernels/io/read.h"
#include "kernels/plugins/vtk/vtk_table.h"

namespace selfsim::io {

Dataset read_vtk(const std::filesystem::path& file, bool unstructured) {
  // Loaded once (a failed load is tried again on the next call).
  static const VtkTable& table = *static_cast<const VtkTable*>(plugin_table(vtk_plugin, vtk_table_symbol));
  return table.read_vtk(file, unstructured);
}

}  // namespace selfsim::io
