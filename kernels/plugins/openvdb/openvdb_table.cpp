// The OpenVDB plugin's one exported function: its table (openvdb_table.h).
#include "kernels/plugins/openvdb/openvdb_table.h"

namespace {

const selfsim::OpenVdbTable table{
    selfsim::boundary_size,
    selfsim::volume_boundary,
    selfsim::distance_vdb,
    [](const selfsim::Volume& v, double voxel, double depth, const selfsim::PointBudget& budget,
       selfsim::Progress& progress,
       double outside) { return selfsim::WallGrid(v, voxel, depth, budget, progress, outside); },
    selfsim::WallGrid::size,
    [](const selfsim::WallGrid& g, std::span<const selfsim::Vec3> p, std::span<double> out) { g.clearances(p, out); },
    [](const selfsim::WallGrid& g) { return g.voxel(); },
    selfsim::io::read_vdb_info,
    selfsim::io::read_vdb_surface,
    selfsim::print::grid_thicken_size,
    selfsim::print::thicken_on_grid,
    selfsim::print::round_tube_size,
    selfsim::print::round_tube_on_grid,
};

}  // namespace

extern "C" __attribute__((visibility("default"))) const void* selfsim_openvdb_table() { return &table; }
