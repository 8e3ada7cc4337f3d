// The .vdb reader's checks of a grid before it is meshed (see vdb_grid_checks.h). Only openvdb.h: no
// OpenVDB tool header, so this translation unit stays light beside vdb_read.cpp.
#include "kernels/plugins/openvdb/vdb_grid_checks.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>

#include "kernels/base/budget.h"
#include "kernels/base/check.h"
#include "kernels/base/count_text.h"
#include "kernels/base/error.h"
#include "kernels/io/dataset/dataset.h"
#include "kernels/io/read_error.h"

namespace selfsim::io {

std::uint64_t meta_count(const openvdb::GridBase& g, const char* key) {
  if (auto m = g.getMetadata<openvdb::Int64Metadata>(key))
    return static_cast<std::uint64_t>(std::max<openvdb::Int64>(m->value(), 0));
  return 0;
}

void check_declared_memory(const openvdb::GridBase& g, std::uint64_t file_bytes) {
  const std::uint64_t declared = vdb_reading_bytes(meta_count(g, openvdb::GridBase::META_FILE_MEM_BYTES),
                                                   meta_count(g, openvdb::GridBase::META_FILE_VOXEL_COUNT), file_bytes);
  if (declared > read_budget_bytes() / 4)
    throw Error("grid '" + shown(g.getName()) + "' declares " + std::to_string(declared >> 20) +
                " MiB, over the reading limit of " + std::to_string(read_budget_bytes() / 4 >> 20) + " MiB");
}

namespace {

// How far out a grid may reach. Its surface's positions come back as single-precision floats (24 bits),
// which resolve an eighth of a voxel out to 2^21 voxels from the world origin; farther, its points snap
// together and its polygons cross. Its integer index coordinates (32 bits) overflow in OpenVDB's own
// arithmetic near 2^31: 2^30 leaves room for a root tile's 4096 voxels and the band around it.
constexpr double farthest_world_voxels = 1 << 21;
constexpr double farthest_index = 1 << 30;

// A grid's value as the float it is ("-0.3", not "-0.30000001192093").
std::string float_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.7g", v);
  return buf;
}

std::string coord_text(const openvdb::Coord& c) {
  return "(" + std::to_string(c[0]) + ", " + std::to_string(c[1]) + ", " + std::to_string(c[2]) + ")";
}

// Walking inward from `from`, an outermost active voxel on `side` (0: the least x, 1: the greatest x, 2: the
// least y, ...), through the active values in a line, the first that lies on the other side of the iso value
// from the inside (0 for a level set, 0.5 for a fog volume): where the surface they hold is crossed. None
// when the active values end first. A tile is crossed at once (a root tile is 4096 voxels across).
std::optional<openvdb::Coord> crossing_inward(const openvdb::FloatGrid& grid, openvdb::Coord c, int side, bool fog) {
  using Tree = openvdb::FloatTree;
  using Upper = Tree::RootNodeType::ChildNodeType;
  using Lower = Upper::ChildNodeType;
  // The width, in log2 voxels, of what a value at each depth stands for: a root tile, a tile of each
  // internal node, a voxel.
  constexpr int log2_width[] = {Upper::TOTAL, Lower::TOTAL, Lower::ChildNodeType::TOTAL, 0};
  const auto access = grid.getConstAccessor();
  const int axis = side / 2, inward = side % 2 ? -1 : 1;
  for (int steps = 0; steps < (1 << 16); ++steps) {  // far more than a grid within 2^30 of the origin has
    const int depth = access.getValueDepth(c);
    if (depth < 0 || depth > 3 || !access.isValueOn(c)) return std::nullopt;
    const double v = access.getValue(c);
    if (fog ? v <= 0.5 : v >= 0) return c;
    const openvdb::Int32 width = openvdb::Int32(1) << log2_width[depth];
    const openvdb::Int32 start = c[axis] & ~(width - 1);  // of the tile holding c
    c[axis] = inward > 0 ? start + width : start - 1;
  }
  return std::nullopt;
}

}  // namespace

void check_grid(const openvdb::FloatGrid& grid, bool fog) {
  const std::string name = "grid '" + shown(grid.getName()) + "'";
  const double background = grid.background();
  if (!std::isfinite(background)) throw Error(name + " has a background that is not finite");
  // The background is the value everywhere outside the stored voxels: it says which side is outside.
  if (!fog && background < 0)
    throw Error(name + " is inside out: its background (the value outside) is " + float_text(background) +
                ", negative, where a level set is negative inside and positive outside; negate its values and "
                "background and save it again");
  if (fog && background > 0.5)
    throw Error(name + " is inside out: its background (the density outside) is " + float_text(background) +
                ", above the 0.5 its surface is drawn at; save it with an empty (0) background");
  // Each of the 6 outermost active voxels (or tiles), one along each axis each way.
  std::array<openvdb::Coord, 6> outermost;
  bool any = false;
  for (auto v = grid.cbeginValueOn(); v; ++v) {
    openvdb::CoordBBox box;
    v.getBoundingBox(box);
    for (int k = 0; k < 3; ++k) {
      if (!any || box.min()[k] < outermost[2 * k][k]) outermost[2 * k] = box.min();
      if (!any || box.max()[k] > outermost[2 * k + 1][k]) outermost[2 * k + 1] = box.max();
    }
    any = true;
  }
  if (!any) return;
  const openvdb::Vec3d size = grid.voxelSize();
  const double voxel = std::min({size[0], size[1], size[2]});
  double index = 0, world = 0;  // the farthest, in voxels
  openvdb::Coord far_index, far_world;
  for (const openvdb::Coord& c : outermost) {
    const openvdb::Vec3d w = grid.indexToWorld(c);
    for (int k = 0; k < 3; ++k) {
      if (std::abs(static_cast<double>(c[k])) > index) index = std::abs(static_cast<double>(c[k])), far_index = c;
      if (std::abs(w[k]) / voxel > world) world = std::abs(w[k]) / voxel, far_world = c;
    }
  }
  if (!(world <= farthest_world_voxels)) {
    const openvdb::Vec3d w = grid.indexToWorld(far_world);
    throw Error(name + " lies " + count_text(std::round(world)) + " voxels from the origin (its voxel at index " +
                coord_text(far_world) + " is at (" + number_text(w[0]) + ", " + number_text(w[1]) + ", " +
                number_text(w[2]) + ")), beyond the " + count_text(farthest_world_voxels) +
                " within which single-precision positions resolve its voxels; move it nearer the origin and save it "
                "again");
  }
  if (!(index <= farthest_index))
    throw Error(name + " reaches index " + coord_text(far_index) + ", beyond the " + count_text(farthest_index) +
                " voxels from index (0, 0, 0) within which OpenVDB's integer coordinates do not overflow; move its "
                "voxels nearer index (0, 0, 0) (its transform keeps where they lie) and save it again");
  // Just beyond the outermost active values lies either outside or an inside that goes on in inactive
  // values (an active tile beside an inactive one, both inside). It is outside, and the grid inside out
  // (its values negated, its background left as it was), when the active values met walking inward from
  // there cross to the other side: the surface they hold then faces the wrong way. Negating a grid whose
  // active values never cross would truly invert it.
  const auto access = grid.getConstAccessor();
  for (int side = 0; side < 6; ++side) {
    openvdb::Coord beyond = outermost[side];
    beyond[side / 2] += side % 2 ? 1 : -1;
    const double value = access.getValue(beyond);
    if (fog ? value > 0.5 : value < 0) {
      const std::optional<openvdb::Coord> crossing = crossing_inward(grid, outermost[side], side, fog);
      if (!crossing) continue;
      throw Error(name + " is inside out: just outside its active voxels it is " + float_text(value) + " (at index " +
                  coord_text(beyond) + "), and inward its active values cross to " +
                  float_text(access.getValue(*crossing)) + " (at index " + coord_text(*crossing) + "), where " +
                  (fog ? "a fog volume is dense inside and empty outside; make it 0 outside"
                       : "a level set is negative inside and positive outside; negate its values") +
                  " and save it again");
    }
  }
}

// Counts the voxels on a tile's faces as its surface (an inactive tile is not meshed). A face is left out when
// just beyond it lies a tile at least as large, or the background, on the same side of `iso`: aligned as
// the tree's nodes are, that value covers the whole face, so no surface crosses it (the inside of a large
// shape filled with tiles weighs only its outer faces).
Tiles active_tiles(const openvdb::FloatGrid& grid, double iso) {
  Tiles t;
  const auto access = grid.getConstAccessor();
  auto it = grid.cbeginValueOn();
  it.setMaxDepth(openvdb::FloatGrid::ValueOnCIter::LEAF_DEPTH - 1);  // tiles only, no leaf voxel
  for (; it; ++it) {
    openvdb::CoordBBox box;
    it.getBoundingBox(box);
    const double d = box.dim().x();
    const bool below = *it < iso;
    ++t.count;
    for (int face = 0; face < 6; ++face) {
      openvdb::Coord beyond = box.min() + openvdb::Coord(static_cast<openvdb::Int32>(d / 2));
      beyond[face / 2] = face % 2 ? box.max()[face / 2] + 1 : box.min()[face / 2] - 1;
      const int depth = access.getValueDepth(beyond);  // -1: the background; 0: a root tile; 3: a voxel
      const bool covered = depth <= static_cast<int>(it.getDepth()) && (access.getValue(beyond) < iso) == below;
      if (!covered) t.surface += d * d;
    }
  }
  return t;
}

// Active voxels, a tile's counted voxel by voxel (activeVoxelCount, counted in a double: a few thousand
// root tiles of 2^36 voxels each would overflow 64 bits).
double active_voxels(const openvdb::FloatGrid& grid) {
  double n = static_cast<double>(grid.tree().activeLeafVoxelCount());
  auto it = grid.cbeginValueOn();
  it.setMaxDepth(openvdb::FloatGrid::ValueOnCIter::LEAF_DEPTH - 1);
  for (; it; ++it) n += static_cast<double>(it.getVoxelCount());
  return n;
}

// Weighs what send_surface announced before meshing: its active tiles' surface (a point and two triangles
// a voxel of their faces) and the voxels it would send, against the run's point budget and the reading
// limit. Throws BudgetError or Error; the child is then ended before it meshes or sends anything more.
void weigh(const VdbSurface& s, const std::filesystem::path& named, const VdbReadOptions& opt, const Tiles& tiles,
           double voxels) {
  const double surface = tiles.surface;
  if (!(surface >= 0 && voxels >= 0 && (tiles.count > 0 || surface == 0)))
    throw Error("the OpenVDB reader sent a malformed answer");
  const std::string grid = "grid '" + shown(s.grid) + "' in '" + one_line(named.string()) + "'";
  const std::string tile_text = std::to_string(tiles.count) + " active tile" + (tiles.count == 1 ? "" : "s");
  if (tiles.count > 0) check_budget(3 * surface, opt.budget, "the surface of the " + tile_text + " of " + grid);
  if (voxels == 0) return;
  check_budget(voxels, opt.budget,
               "the voxels of " + grid + (tiles.count > 0 ? " (its " + tile_text + " as voxels)" : std::string()));
  const double most = static_cast<double>(read_budget_bytes() / 32);  // 16 bytes a sample, twice over
  if (voxels > most)
    throw Error("grid '" + shown(s.grid) + "' has " + count_text(voxels) + " active voxels" +
                (tiles.count > 0 ? " (its " + tile_text + " as voxels)" : std::string()) +
                ", over the reading limit of " + count_text(most) + " voxels");
}

}  // namespace selfsim::io
