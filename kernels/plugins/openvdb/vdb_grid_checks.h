// What the .vdb reader (vdb_read.cpp) checks of a grid before it meshes it (internal to
// kernels/plugins/openvdb): in the reading child, the memory its metadata lets it take before any voxel is
// read, whether it would mesh into its own surface, and what its active tiles weigh; in the parent, those
// weights against the run's point budget and the reading limit, before anything is meshed or sent.
#pragma once

#include <openvdb/openvdb.h>

#include <cstdint>
#include <filesystem>
#include <string>

#include "kernels/io/vdb/vdb_read.h"

namespace selfsim::io {

// A metadata count that OpenVDB writes with every grid (META_FILE_MEM_BYTES, META_FILE_VOXEL_COUNT); 0
// where the file does not say.
std::uint64_t meta_count(const openvdb::GridBase& g, const char* key);

// Refuses, before its voxels are read, a grid whose reading would take over the reading limit by what it
// declares (vdb_reading_bytes), in a file of `file_bytes`.
void check_declared_memory(const openvdb::GridBase& g, std::uint64_t file_bytes);

// Refuses a grid that would mesh into something else than its surface (inside out, far out), saying what is
// wrong with the grid.
void check_grid(const openvdb::FloatGrid& grid, bool fog);

// A grid's active tiles: how many, and the voxels on their faces that may be on its surface, at most one
// point of volumeToMesh's each.
struct Tiles {
  std::uint64_t count = 0;
  double surface = 0;
};
Tiles active_tiles(const openvdb::FloatGrid& grid, double iso);

// Active voxels, a tile's counted voxel by voxel, in a double.
double active_voxels(const openvdb::FloatGrid& grid);

// In the parent: weighs what the child announced of grid `s.grid` in `named` (its tiles, and the voxels it
// would send) against opt.budget and the reading limit. Throws BudgetError or Error.
void weigh(const VdbSurface& s, const std::filesystem::path& named, const VdbReadOptions& opt, const Tiles& tiles,
           double voxels);

}  // namespace selfsim::io
