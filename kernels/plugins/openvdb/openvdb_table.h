// The functions of the OpenVDB plugin (selfsim_openvdb.so, plugin.h): everything selfsim does with
// OpenVDB, behind level_set.h, wall_grid.h and vdb_read.h.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "kernels/io/vdb/vdb_read.h"
#include "kernels/print/grid_thicken.h"
#include "kernels/print/grid_tube.h"
#include "kernels/region/level_set.h"
#include "kernels/region/wall_grid.h"

namespace selfsim {

struct OpenVdbTable {
  double (*boundary_size)(const Volume&, double);
  Mesh (*volume_boundary)(const Volume&, double, const PointBudget&, Progress&);
  std::string (*distance_vdb)(const Mesh&, bool, double, const std::string&, const PointBudget&, Progress&);
  WallGrid (*wall_grid)(const Volume&, double, double, const PointBudget&, Progress&, double);
  double (*wall_grid_size)(const Volume&, double, double, double);
  void (*wall_clearances)(const WallGrid&, std::span<const Vec3>, std::span<double>);
  double (*wall_voxel)(const WallGrid&);
  std::vector<io::VdbGridInfo> (*read_vdb_info)(const std::filesystem::path&);
  io::VdbSurface (*read_vdb_surface)(const std::filesystem::path&, const io::VdbReadOptions&);
  double (*grid_thicken_size)(const Mesh&, const print::GridThickenOptions&);
  Mesh (*thicken_on_grid)(const Mesh&, const print::GridThickenOptions&, Progress&);
  double (*round_tube_size)(const std::vector<print::RoundSegment>&, double);
  Mesh (*round_tube_on_grid)(const std::vector<print::RoundSegment>&, const print::GridTubeOptions&, Progress&);
};

inline constexpr const char* openvdb_plugin = "selfsim_openvdb.so";
inline constexpr const char* openvdb_table_symbol = "selfsim_openvdb_table";

}  // namespace selfsim
