// level_set.h, wall_grid.h and vdb_read.h forwarded to the OpenVDB plugin (plugin.h), loaded on first use.
#include "kernels/base/plugin.h"
#include "kernels/plugins/openvdb/openvdb_table.h"
#include "kernels/print/grid_thicken.h"

namespace selfsim {

namespace {

// Loaded once (a failed load is tried again on the next call).
const OpenVdbTable& openvdb() {
  static const OpenVdbTable& table =
      *static_cast<const OpenVdbTable*>(plugin_table(openvdb_plugin, openvdb_table_symbol));
  return table;
}

}  // namespace

double boundary_size(const Volume& v, double voxel) { return openvdb().boundary_size(v, voxel); }

Mesh volume_boundary(const Volume& v, double voxel, const PointBudget& budget, Progress& progress) {
  return openvdb().volume_boundary(v, voxel, budget, progress);
}

std::string distance_vdb(const Mesh& m, bool closed, double voxel, const std::string& name, const PointBudget& budget,
                         Progress& progress) {
  return openvdb().distance_vdb(m, closed, voxel, name, budget, progress);
}

WallGrid::WallGrid(const Volume& v, double voxel, double depth, const PointBudget& budget, Progress& progress,
                   double outside)
    : WallGrid(openvdb().wall_grid(v, voxel, depth, budget, progress, outside)) {}

double WallGrid::size(const Volume& v, double voxel, double depth, double outside) {
  return openvdb().wall_grid_size(v, voxel, depth, outside);
}

void WallGrid::clearances(std::span<const Vec3> points, std::span<double> out) const {
  openvdb().wall_clearances(*this, points, out);
}

double WallGrid::voxel() const { return openvdb().wall_voxel(*this); }

namespace print {

double grid_thicken_size(const Mesh& m, const GridThickenOptions& opt) { return openvdb().grid_thicken_size(m, opt); }

Mesh thicken_on_grid(const Mesh& m, const GridThickenOptions& opt, Progress& progress) {
  return openvdb().thicken_on_grid(m, opt, progress);
}

}  // namespace print

namespace io {

std::vector<VdbGridInfo> read_vdb_info(const std::filesystem::path& file) { return openvdb().read_vdb_info(file); }

VdbSurface read_vdb_surface(const std::filesystem::path& file, const VdbReadOptions& opt) {
  return openvdb().read_vdb_surface(file, opt);
}

}  // namespace io

}  // namespace selfsim
