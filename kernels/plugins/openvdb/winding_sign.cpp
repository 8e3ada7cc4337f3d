#include "kernels/plugins/openvdb/winding_sign.h"

#include <openvdb/tools/SignedFloodFill.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>
#include <vector>

namespace selfsim::vdb {

namespace {

// Vertices in fixed point (1/65536 of a voxel) so that which lattice lines cross which triangle is decided
// exactly: two triangles sharing an edge always agree whether a line passes left or right of it, so a line
// through an edge or a vertex counts one crossing, never zero or two. A frame is at most 2^20 voxels across:
// coordinates under 2^37, their products under 2^75.
constexpr double fixed = 65536;
struct P {
  std::int64_t x, y;
};

// Which side of the edge u→v the lattice point p lies on (+1 left), for p moved by (e, e²) with e
// infinitesimal when it lies on the edge's line (simulation of simplicity: never 0, and the edge v→u
// always answers the opposite).
int side(P u, P v, P p) {
  const __int128 e = static_cast<__int128>(v.x - u.x) * (p.y - u.y) - static_cast<__int128>(v.y - u.y) * (p.x - u.x);
  if (e != 0) return e > 0 ? 1 : -1;
  if (v.y != u.y) return v.y < u.y ? 1 : -1;
  return v.x > u.x ? 1 : -1;
}

double edge_value(P u, P v, P p) {
  return static_cast<double>(static_cast<__int128>(v.x - u.x) * (p.y - u.y) -
                             static_cast<__int128>(v.y - u.y) * (p.x - u.x));
}

// Where the lattice line (i, j) (along z) passes through a triangle, and how the winding changes above it.
struct Crossing {
  std::int32_t i, j;
  float z;
  std::int8_t delta;
  bool operator<(const Crossing& o) const { return std::tie(i, j, z) < std::tie(o.i, o.j, o.z); }
};

std::int64_t floor_div(std::int64_t a) { return static_cast<std::int64_t>(std::floor(static_cast<double>(a) / fixed)); }

void triangle_crossings(const P (&corner)[3], const double (&z)[3], std::vector<Crossing>& out) {
  P a = corner[0], b = corner[1], c = corner[2];
  double za = z[0], zb = z[1], zc = z[2];
  const __int128 area = static_cast<__int128>(b.x - a.x) * (c.y - a.y) - static_cast<__int128>(b.y - a.y) * (c.x - a.x);
  if (area == 0) return;  // seen edge-on: no line passes through it (its neighbours' edges decide)
  // Facing up (+z), a line going up leaves the solid through it: the winding above is one less.
  const std::int8_t delta = area > 0 ? -1 : 1;
  if (area < 0) {
    std::swap(b, c);
    std::swap(zb, zc);
  }
  const double total = static_cast<double>(area > 0 ? area : -area);
  const std::int64_t i0 = floor_div(std::min({a.x, b.x, c.x})), i1 = floor_div(std::max({a.x, b.x, c.x})) + 1;
  const std::int64_t j0 = floor_div(std::min({a.y, b.y, c.y})), j1 = floor_div(std::max({a.y, b.y, c.y})) + 1;
  const P corners[3] = {a, b, c};
  for (std::int64_t j = j0; j <= j1; ++j) {
    // The row's span of the triangle (in floating point, widened by a line each side); the exact test
    // decides each line in it.
    const double y = static_cast<double>(j) * fixed;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (int k = 0; k < 3; ++k) {
      const P u = corners[k], v = corners[(k + 1) % 3];
      if ((u.y <= y && y <= v.y) || (v.y <= y && y <= u.y)) {
        const double x = u.y == v.y ? static_cast<double>(u.x)
                                    : u.x + (y - u.y) / static_cast<double>(v.y - u.y) * static_cast<double>(v.x - u.x);
        lo = std::min({lo, x, u.y == v.y ? static_cast<double>(v.x) : x});
        hi = std::max({hi, x, u.y == v.y ? static_cast<double>(v.x) : x});
      }
    }
    if (!(lo <= hi)) continue;
    const std::int64_t from = std::max(i0, static_cast<std::int64_t>(std::floor(lo / fixed)) - 1);
    const std::int64_t to = std::min(i1, static_cast<std::int64_t>(std::ceil(hi / fixed)) + 1);
    for (std::int64_t i = from; i <= to; ++i) {
      const P p{i * static_cast<std::int64_t>(fixed), j * static_cast<std::int64_t>(fixed)};
      if (side(a, b, p) < 0 || side(b, c, p) < 0 || side(c, a, p) < 0) continue;
      const double wa = edge_value(b, c, p), wb = edge_value(c, a, p), wc = edge_value(a, b, p);
      out.push_back({static_cast<std::int32_t>(i), static_cast<std::int32_t>(j),
                     static_cast<float>((wa * za + wb * zb + wc * zc) / total), delta});
    }
  }
}

}  // namespace

void sign_by_winding(Grid& g, const Mesh& m, const Frame& f, Interrupter& interrupt) {
  std::vector<P> points;
  std::vector<double> heights;
  points.reserve(m.points.size());
  heights.reserve(m.points.size());
  for (const Vec3& p : m.points) {
    const Vec3 q = (1 / f.voxel) * (p - f.origin);
    points.push_back({std::llround(q.x * fixed), std::llround(q.y * fixed)});
    heights.push_back(q.z);
  }
  std::vector<Crossing> crossings;
  for (const Triangle& t : m.triangles) {
    const P corner[3] = {points[t[0]], points[t[1]], points[t[2]]};
    const double z[3] = {heights[t[0]], heights[t[1]], heights[t[2]]};
    triangle_crossings(corner, z, crossings);
    if (interrupt.wasInterrupted()) return;
  }
  std::sort(crossings.begin(), crossings.end());

  using Leaf = Grid::TreeType::LeafNodeType;
  std::vector<Leaf*> leaves;
  g.tree().getNodes(leaves);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, leaves.size(), 64),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      if (interrupt.wasInterrupted()) return;
                      for (std::size_t n = r.begin(); n != r.end(); ++n) {
                        Leaf& leaf = *leaves[n];
                        const openvdb::Coord o = leaf.origin();
                        for (int di = 0; di < static_cast<int>(Leaf::DIM); ++di)
                          for (int dj = 0; dj < static_cast<int>(Leaf::DIM); ++dj) {
                            const std::int32_t i = o.x() + di, j = o.y() + dj;
                            const Crossing key{i, j, -std::numeric_limits<float>::infinity(), 0};
                            auto c = std::lower_bound(crossings.begin(), crossings.end(), key);
                            int winding = 0;
                            for (int dk = 0; dk < static_cast<int>(Leaf::DIM); ++dk) {
                              const float k = static_cast<float>(o.z() + dk);
                              for (; c != crossings.end() && c->i == i && c->j == j && c->z < k; ++c)
                                winding += c->delta;
                              const openvdb::Index at = Leaf::coordToOffset(openvdb::Coord(i, j, o.z() + dk));
                              if (!leaf.isValueOn(at)) continue;
                              const float v = std::abs(leaf.getValue(at));
                              leaf.setValueOnly(at, winding != 0 ? -v : v);
                            }
                          }
                      }
                    });
  if (interrupt.wasInterrupted()) return;
  openvdb::tools::signedFloodFill(g.tree());
  g.setGridClass(openvdb::GRID_LEVEL_SET);
}

}  // namespace selfsim::vdb
