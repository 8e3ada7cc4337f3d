// Reading .vdb files back (`selfsim info`, `selfsim preview`) with OpenVDB, whose headers stay in
// vdb_read.cpp. OpenVDB trusts the file, so reading goes the way vtk_read.cpp reads VTK files: sizes the
// file declares are checked against the reading budget first, and OpenVDB then runs in a forked child with
// an address-space and a time limit (child_process.h), single-threaded (TBB's state does not survive a
// fork). Every failure is one line, "cannot read 'FILE': REASON".
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "kernels/base/budget.h"
#include "kernels/io/dataset/dataset.h"
#include "kernels/region/grid_samples.h"

namespace selfsim::io {

// What `selfsim info` prints of one grid, from the grid's metadata alone (no voxel is read).
struct VdbGridInfo {
  std::string name;
  std::string grid_class;  // "level set", "fog volume", "staggered" or "unknown"
  std::string value_type;  // OpenVDB's name: "float", "vec3s", ...
  std::array<double, 3> voxel{};
  std::uint64_t active_voxels = 0;
  bool has_bbox = false;  // false for an empty grid
  std::array<std::int64_t, 3> index_min{}, index_max{};
  std::array<double, 3> world_min{}, world_max{};
};

std::vector<VdbGridInfo> read_vdb_info(const std::filesystem::path& file);

// A .vdb file's surface: the first float grid that is a level set (its zero isosurface) or, failing that,
// the first float grid of any class: a fog volume at density 0.5, another grid at 0 when it holds negative
// values and at half a voxel when it does not (an unsigned distance, as selfsim writes for an open
// surface: its surface thickened by half a voxel). Triangles and quads from OpenVDB's volumeToMesh.
struct VdbSurface {
  Dataset mesh;      // polygons
  std::string grid;  // the grid's name
  std::string what;  // "level set 'surface' at 0", for the user
  // A level set's active voxels, when its transform is a uniform scale and translation (empty otherwise,
  // and for fog volumes and other grids): its walls measured on the grid itself (WallGrid).
  GridSamples samples;
};

struct VdbReadOptions {
  std::string grid;                // the grid to take instead (any float grid); empty: chosen as above
  std::filesystem::path shown_as;  // the name messages give the file (FileBeneath::name()); empty: the file
  // The run's point budget. Active tiles (one value for a block of 8^3, 128^3 or 4096^3 voxels, as Houdini
  // and Blender write) are weighed against it before anything is meshed or sent: their surface, and with
  // `samples` their voxels, so a 2^36-voxel tile is refused at once instead of voxelised.
  PointBudget budget;
  bool samples = false;  // send a level set's voxels (VdbSurface::samples), its active tiles as voxels
};

// Grids that would mesh wrongly are refused with what is wrong with them: a level set inside out (negative
// outside), one so far from its index or world origin that single-precision positions lose its voxels.
VdbSurface read_vdb_surface(const std::filesystem::path& file, const VdbReadOptions& opt = {});

// What reading a grid may take in memory, judged from its metadata before any voxel is read, in a file of
// `file_bytes`: the memory it declares, or 4 bytes for each voxel it declares, whichever is more, so that
// declaring little memory does not hide a count of voxels. Only as many voxels as the file has room for in
// leaves are charged (each leaf of 512 voxels is written with at least its 64-byte mask: 8 a file byte):
// an active tile holds its voxels in one value, and is weighed once read (a 300-byte file's 2^36-voxel
// root tile is no memory). A file that understates both is stopped by the reading child's memory limit.
inline std::uint64_t vdb_reading_bytes(std::uint64_t declared_bytes, std::uint64_t declared_voxels,
                                       std::uint64_t file_bytes) {
  const std::uint64_t leaf_voxels = 8 * std::min(file_bytes, std::uint64_t{1} << 58);
  return std::max(declared_bytes, 4 * std::min(declared_voxels, leaf_voxels));
}

}  // namespace selfsim::io
