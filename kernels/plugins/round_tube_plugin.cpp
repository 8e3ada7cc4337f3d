// grid_tube.h's round cones forwarded to the OpenVDB plugin (plugin.h, openvdb_table.h), as
// openvdb_plugin.cpp forwards the plugin's other functions.
#include "kernels/base/plugin.h"
#include "kernels/plugins/openvdb/openvdb_table.h"
#include "kernels/print/grid_tube.h"

namespace selfsim::print {

namespace {

const OpenVdbTable& openvdb() {
  static const OpenVdbTable& table =
      *static_cast<const OpenVdbTable*>(plugin_table(openvdb_plugin, openvdb_table_symbol));
  return table;
}

}  // namespace

double round_tube_size(const std::vector<RoundSegment>& segments, double voxel) {
  return openvdb().round_tube_size(segments, voxel);
}

Mesh round_tube_on_grid(const std::vector<RoundSegment>& segments, const GridTubeOptions& opt, Progress& progress) {
  return openvdb().round_tube_on_grid(segments, opt, progress);
}

}  // namespace selfsim::print
