// The .vdb reader on files selfsim writes: a sphere's level set meshes back to a closed surface of the
// sphere's radius; info reads the grid's metadata; bad files are one-line errors.
#include "kernels/io/vdb/vdb_read.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "kernels/region/level_set.h"
#include "kernels/region/volume.h"
#include "kernels/region/wall_grid.h"

namespace selfsim::io {
namespace {

std::filesystem::path temp(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("selfsim_vdb_read_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir / name;
}

std::filesystem::path sphere_vdb() {
  const Mesh m = volume_boundary(Volume::sphere({0, 0, 0}, 1), 1.0 / 32, PointBudget{}, no_progress());
  const std::filesystem::path file = temp("sphere.vdb");
  std::ofstream(file, std::ios::binary) << distance_vdb(m, true, 1.0 / 32, "surface", PointBudget{}, no_progress());
  return file;
}

TEST(VdbRead, SphereSurfaceHasItsRadius) {
  const VdbSurface s = read_vdb_surface(sphere_vdb());
  EXPECT_EQ(s.grid, "surface");
  EXPECT_EQ(s.what, "level set 'surface' at 0");
  ASSERT_GT(s.mesh.points.size(), 1000u);
  EXPECT_EQ(s.mesh.shapes, CellShapes::polygons);
  for (const auto& p : s.mesh.points) EXPECT_NEAR(std::hypot(p[0], p[1], p[2]), 1.0, 1.0 / 32);
  EXPECT_EQ(s.mesh.cell_ends.back(), s.mesh.cell_points.size());
}

// A level set's own voxels come back too: each the sphere's signed distance at its centre, and a WallGrid
// measured on them reads the distance inside within its bound, at the file's voxel whatever it is asked.
TEST(VdbRead, ALevelSetsVoxelsComeBackForTheWalls) {
  EXPECT_TRUE(read_vdb_surface(sphere_vdb()).samples.index.empty());  // only when asked
  const VdbSurface s = read_vdb_surface(sphere_vdb(), {.samples = true});
  const GridSamples& g = s.samples;
  EXPECT_DOUBLE_EQ(g.voxel, 1.0 / 32);
  ASSERT_GT(g.index.size(), 10000u);
  ASSERT_EQ(g.index.size(), g.value.size());
  EXPECT_NEAR(g.background, 3.0 / 32, 1e-6);
  for (std::size_t i = 0; i < g.index.size(); i += 7) {
    const Vec3 p = g.origin + g.voxel * Vec3{static_cast<double>(g.index[i][0]), static_cast<double>(g.index[i][1]),
                                             static_cast<double>(g.index[i][2])};
    EXPECT_NEAR(g.value[i], norm(p) - 1, g.voxel / 4) << i;
  }
  Volume v = Volume::closed_mesh(sphere_mesh({0, 0, 0}, 1, 1.0 / 128), no_progress());
  v.samples = std::make_shared<const GridSamples>(g);
  const WallGrid walls(v, 0.2, 0.5, {}, no_progress());
  EXPECT_DOUBLE_EQ(walls.voxel(), 1.0 / 32);
  for (const Vec3 p : {Vec3{0.9, 0, 0}, Vec3{0, -0.7, 0.1}, Vec3{0.3, 0.3, -0.6}, Vec3{0, 1.01, 0}})
    EXPECT_NEAR(walls.clearance(p), 1 - norm(p), walls.error() + 1.0 / 128) << p.y;
  EXPECT_GE(walls.clearance({0.1, 0.2, 0.3}), 0.5);  // deeper than asked: at least that deep
}

TEST(VdbRead, InfoFromMetadata) {
  const std::vector<VdbGridInfo> grids = read_vdb_info(sphere_vdb());
  ASSERT_EQ(grids.size(), 1u);
  EXPECT_EQ(grids[0].name, "surface");
  EXPECT_EQ(grids[0].grid_class, "level set");
  EXPECT_EQ(grids[0].value_type, "float");
  EXPECT_DOUBLE_EQ(grids[0].voxel[0], 1.0 / 32);
  EXPECT_GT(grids[0].active_voxels, 1000u);
  ASSERT_TRUE(grids[0].has_bbox);
  EXPECT_NEAR(grids[0].world_min[0], -1, 0.2);
  EXPECT_NEAR(grids[0].world_max[2], 1, 0.2);
}

TEST(VdbRead, BadFilesAreOneLineErrors) {
  const std::filesystem::path garbage = temp("garbage.vdb");
  std::ofstream(garbage) << "not a vdb file at all";
  for (const std::filesystem::path& f : {garbage, temp("missing.vdb")})
    for (int which = 0; which < 2; ++which) try {
        if (which == 0)
          read_vdb_surface(f);
        else
          read_vdb_info(f);
        ADD_FAILURE() << f << " read";
      } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_EQ(m.rfind("cannot read '" + f.string() + "': ", 0), 0u) << m;
        EXPECT_EQ(m.find('\n'), std::string::npos) << m;
      }
}

// The memory a grid is judged to take before its voxels are read: a declared memory smaller than its voxels
// take does not hide them (it did: a file declaring 1 byte skipped the voxel count), while a tile's voxels,
// more than the file has room for in leaves, are not charged as memory.
TEST(VdbRead, ReadingBytesFromDeclaredMemoryVoxelsAndFileSize) {
  const std::uint64_t mib = std::uint64_t{1} << 20;
  EXPECT_EQ(vdb_reading_bytes(1, 256 * mib, 64 * mib), 1024 * mib);           // leaves' voxels under a lying memory
  EXPECT_EQ(vdb_reading_bytes(0, 256 * mib, 64 * mib), 1024 * mib);           // no memory declared
  EXPECT_EQ(vdb_reading_bytes(2048 * mib, 256 * mib, 64 * mib), 2048 * mib);  // more memory than voxels
  // A root tile (2^36 voxels) in a 300-byte file: only the 2,400 voxels its leaves could hold.
  EXPECT_EQ(vdb_reading_bytes(1, std::uint64_t{1} << 36, 300), 4u * 2400);
  // No overflow, whatever the counts.
  EXPECT_EQ(vdb_reading_bytes(0, ~std::uint64_t{0}, ~std::uint64_t{0}), std::uint64_t{1} << 63);
}

TEST(VdbRead, TruncatedFileIsAnError) {
  const std::filesystem::path whole = sphere_vdb(), cut = temp("cut.vdb");
  std::ifstream in(whole, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), {});
  std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  EXPECT_THROW(read_vdb_surface(cut), Error);
}

}  // namespace
}  // namespace selfsim::io
