// The grid of candidate pairs that both searches of mesh_intersections.h share: first_intersection's
// (mesh_intersections.cpp, which also builds the grid) and intersecting_pairs' and classified_pairs'
// (mesh_contact_pairs.cpp). Internal to those two files.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "kernels/base/progress.h"
#include "kernels/geom/mesh.h"
#include "kernels/geom/mesh_intersections.h"

namespace selfsim::candidate_grid {

// ---- The grid: candidate pairs are triangles whose boxes (grown by eps) share a cell.
//
// Boxes are floats in units of the mesh's diagonal from its low corner (24 bytes a triangle instead of 48),
// widened by 2^-23 so that rounding only ever grows them. Every (cell, triangle) insertion is one 64-bit
// record, the cell's Morton code above the triangle's index, radix-sorted by cell: cells then come in an
// order that sweeps space, so neighbouring cells find their triangles still in cache (a hash table of cells
// visits them in random order and misses the cache on most triangles it gathers). The sort is stable and
// the records start in triangle order, so each cell's run lists its triangles in increasing index.

struct Box {
  std::array<float, 3> lo, hi;
};

using Cell = std::array<std::uint32_t, 3>;

// The low 21 bits of x moved to every third bit (bit k to bit 3k), in five shifts of halving width.
inline std::uint64_t spread(std::uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x001f00000000ffffull;
  x = (x | x << 16) & 0x001f0000ff0000ffull;
  x = (x | x << 8) & 0x100f00f00f00f00full;
  x = (x | x << 4) & 0x10c30c30c30c30c3ull;
  x = (x | x << 2) & 0x1249249249249249ull;
  return x;
}
// The inverse: every third bit of x, from bit 0, packed together.
inline std::uint32_t compact(std::uint64_t x) {
  x &= 0x1249249249249249ull;
  x = (x | x >> 2) & 0x10c30c30c30c30c3ull;
  x = (x | x >> 4) & 0x100f00f00f00f00full;
  x = (x | x >> 8) & 0x001f0000ff0000ffull;
  x = (x | x >> 16) & 0x001f00000000ffffull;
  x = (x | x >> 32) & 0x1fffffull;
  return static_cast<std::uint32_t>(x);
}

inline int bit_width(std::uint64_t x) { return x == 0 ? 0 : 64 - __builtin_clzll(x); }

struct Grid {
  std::array<float, 3> per_unit{1, 1, 1};  // cells per unit of the diagonal, on each axis
  std::array<std::uint32_t, 3> last{};     // the highest cell index on each axis
  int id_bits = 1;                         // the records' low bits hold the triangle index

  std::uint32_t cell(float u, int axis) const {
    // Boxes start a little below 0: truncation toward zero takes those to cell 0, as floor would.
    return std::min(static_cast<std::uint32_t>(std::max(static_cast<std::int32_t>(u * per_unit[axis]), 0)), last[axis]);
  }
  Cell low(const Box& b) const { return {cell(b.lo[0], 0), cell(b.lo[1], 1), cell(b.lo[2], 2)}; }
  Cell high(const Box& b) const { return {cell(b.hi[0], 0), cell(b.hi[1], 1), cell(b.hi[2], 2)}; }
  static std::uint64_t cells(const Cell& lo, const Cell& hi) {
    return std::uint64_t{hi[0] - lo[0] + 1} * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1);
  }
  std::uint64_t cells(const Box& b) const { return cells(low(b), high(b)); }
  static std::uint64_t key(const Cell& c) { return spread(c[0]) | spread(c[1]) << 1 | spread(c[2]) << 2; }
  static Cell cell_of(std::uint64_t key) { return {compact(key), compact(key >> 1), compact(key >> 2)}; }
  int key_bits() const { return 3 * bit_width(std::max({last[0], last[1], last[2]})); }
};

inline bool overlap(const Box& a, const Box& b) {
  return (a.lo[0] <= b.hi[0]) & (b.lo[0] <= a.hi[0]) & (a.lo[1] <= b.hi[1]) & (b.lo[1] <= a.hi[1]) &
         (a.lo[2] <= b.hi[2]) & (b.lo[2] <= a.hi[2]);
}

// The mesh's corners moved and scaled so that its box starts at the origin and has diagonal 1: every test
// then works at one scale (a gap of eps = 1e-9 means the same in millimetres and in light years, and no
// square of a coordinate overflows or underflows).
struct Corners {
  const Mesh& m;
  Vec3 origin;
  double size;   // the diagonal, or 1 for a mesh of one point
  double scale;  // 1 / size

  Vec3 at(std::uint32_t p) const { return (m.points[p] - origin) * scale; }
  std::array<Vec3, 3> operator()(std::uint32_t i) const {
    const Triangle& t = m.triangles[i];
    return {at(t[0]), at(t[1]), at(t[2])};
  }
};

// The candidate pairs' grid over m's triangles, scaled to a unit diagonal: what both searches share.
struct Candidates {
  Corners corners;
  std::vector<Box> boxes;
  Grid grid;
  std::vector<std::uint64_t> records;
  static constexpr double eps = 1e-9;  // of the diagonal, which is 1 now

  // Boxes, the grid and its sorted records: progress to 0.2 of its range.
  Candidates(const Mesh& m, const BBox3& bounds, double size, Progress& progress);

  // Where triangles i and j meet, in m's coordinates.
  TrianglePair pair(std::uint32_t i, std::uint32_t j) const;
};

// Throws Error for a non-finite point or an index out of range (counted from 1), or too many triangles.
void check_input(const Mesh& m);

// The mesh's box and its diagonal (1 for a mesh of one point); Error when the diagonal overflows.
double diagonal_of(const Mesh& m, BBox3& bounds);

}  // namespace selfsim::candidate_grid
