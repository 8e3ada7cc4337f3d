// Tubes whose radius changes along the curve (grid_tube.h), on an OpenVDB grid: the signed distance to the
// union of round cones (round_cone.h) sampled on a narrow band of voxels, then meshed (iso_surface).
//
// OpenVDB's own tubes of varying radius (tools/LevelSetTubes.h) came after Debian's 10.0, so the band is
// written here, block by block: each cone is listed with the 8³-voxel blocks (OpenVDB's leaves) its band
// reaches, a block wholly inside one cone is dropped (its inside is signed by the flood fill from the band
// around it), and each listed block's voxels take the least distance of its cones. Memory is the band's, not
// the solid's inside: a trunk's thick core costs nothing. The (block, cone) pairs are one flat list, sorted
// by block, 16 bytes a pair, reserved at the count of blocks the cones' boxes reach (what the size predicts):
// hash maps of lists cost about 100 bytes a block.
#include <openvdb/openvdb.h>
#include <openvdb/tools/SignedFloodFill.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include "kernels/base/budget.h"
#include "kernels/base/check.h"
#include "kernels/geom/mesh_check.h"
#include "kernels/plugins/openvdb/grid_frame.h"
#include "kernels/print/grid_tube.h"

namespace selfsim::print {

namespace {

constexpr int block = 8;                                  // OpenVDB's leaf: 8 voxels a side
constexpr double block_reach = 0.8660254037844386 * 7.0;  // from a block's centre to its farthest voxel centre
constexpr float band = 3;                                 // voxels of band each side of the surface

// The frame around every cone, grown by its radius and two voxels.
vdb::Frame frame_around(const std::vector<RoundSegment>& s, double voxel) {
  BBox3 box{s[0].a, s[0].a};
  for (const RoundSegment& c : s)
    for (const auto& [p, r] : {std::pair{c.a, c.ra}, std::pair{c.b, c.rb}}) {
      const double m = r + 2 * voxel;
      box.min = {std::min(box.min.x, p.x - m), std::min(box.min.y, p.y - m), std::min(box.min.z, p.z - m)};
      box.max = {std::max(box.max.x, p.x + m), std::max(box.max.y, p.y + m), std::max(box.max.z, p.z + m)};
    }
  return vdb::frame_for(box, voxel);
}

// The cone in the frame's voxels.
RoundSegment local(const RoundSegment& c, const vdb::Frame& f) {
  const auto v = [&](Vec3 p) {
    const openvdb::Vec3s q = f.local(p);
    return Vec3{q.x(), q.y(), q.z()};
  };
  return {v(c.a), v(c.b), c.ra / f.voxel, c.rb / f.voxel};
}

// The reach of a cone's band beyond its axis, in voxels.
double reach_of(const RoundSegment& c) { return std::max(c.ra, c.rb) + band + 1; }

// How many blocks blocks_near visits (c in the frame's voxels).
double blocks_count(const RoundSegment& c) {
  const double r = reach_of(c);
  double n = 1;
  for (const auto& [a, b] : {std::pair{c.a.x, c.b.x}, std::pair{c.a.y, c.b.y}, std::pair{c.a.z, c.b.z}})
    n *= std::floor((std::max(a, b) + r) / block) - std::floor((std::min(a, b) - r) / block) + 1;
  return n;
}

// The blocks (by their lowest voxel / 8) a cone's box and band reach.
template <class Visit>
void blocks_near(const RoundSegment& c, Visit&& visit) {
  const double r = reach_of(c);
  std::array<std::int64_t, 3> lo, hi;
  const std::array<double, 6> ends{std::min(c.a.x, c.b.x), std::min(c.a.y, c.b.y), std::min(c.a.z, c.b.z),
                                   std::max(c.a.x, c.b.x), std::max(c.a.y, c.b.y), std::max(c.a.z, c.b.z)};
  for (int k = 0; k < 3; ++k) {
    lo[k] = static_cast<std::int64_t>(std::floor((ends[k] - r) / block));
    hi[k] = static_cast<std::int64_t>(std::floor((ends[k + 3] + r) / block));
  }
  for (std::int64_t i = lo[0]; i <= hi[0]; ++i)
    for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
      for (std::int64_t k = lo[2]; k <= hi[2]; ++k) visit(i, j, k);
}

std::uint64_t key_of(std::int64_t i, std::int64_t j, std::int64_t k) {
  // Blocks of a frame at most 2^20 voxels across (frame_for): 2^17 of them and a margin, 21 bits each.
  constexpr std::int64_t off = 1 << 20;
  return static_cast<std::uint64_t>(i + off) << 42 | static_cast<std::uint64_t>(j + off) << 21 |
         static_cast<std::uint64_t>(k + off);
}
std::array<std::int64_t, 3> block_of(std::uint64_t key) {
  constexpr std::int64_t off = 1 << 20, mask = (1 << 21) - 1;
  return {static_cast<std::int64_t>(key >> 42) - off, static_cast<std::int64_t>((key >> 21) & mask) - off,
          static_cast<std::int64_t>(key & mask) - off};
}

// A block and one cone whose band reaches it, or `inside` for a block wholly inside some cone.
struct Pair {
  std::uint64_t key;
  std::uint32_t cone;
  bool operator<(const Pair& o) const { return key != o.key ? key < o.key : cone < o.cone; }
};
constexpr std::uint32_t inside = std::numeric_limits<std::uint32_t>::max();

double lateral_area(const RoundSegment& c) {
  const double l = norm(c.b - c.a), r = std::max(c.ra, c.rb);
  return std::numbers::pi * (c.ra + c.rb) * std::hypot(l, c.ra - c.rb) + 4 * std::numbers::pi * r * r;
}

}  // namespace

double round_tube_size(const std::vector<RoundSegment>& segments, double voxel) {
  if (segments.empty()) return 0;
  const vdb::Frame f = frame_around(segments, voxel);
  double area = 0, pairs = 0;
  std::vector<Vec3> corners;
  corners.reserve(2 * segments.size());
  for (const RoundSegment& c : segments) {
    area += lateral_area(c);
    corners.push_back(c.a);
    corners.push_back(c.b);
    pairs += blocks_count(local(c, f));
  }
  // The cones twice (the caller's and the frame's copy), the band's leaves, whole blocks 8 voxels across (and
  // inner nodes), the list of (block, cone) pairs, and the meshed surface (its points and twice as many
  // triangles at the voxel's spacing). Budget points are 16 bytes.
  const double cones = 2 * static_cast<double>(segments.size() * sizeof(RoundSegment)) / 16;
  const double list = pairs * static_cast<double>(sizeof(Pair)) / 16;
  return cones + vdb::tree_size(corners, area, f, 2 * block) + list + 3 * area / (voxel * voxel);
}

Mesh round_tube_on_grid(const std::vector<RoundSegment>& segments, const GridTubeOptions& opt, Progress& progress) {
  if (segments.empty()) throw Error("the curve has no segment of non-zero length to make a tube of");
  const double voxel = opt.voxel;
  check_budget(round_tube_size(segments, voxel), opt.budget,
               "a tube on a grid at voxel size " + voxel_text(voxel) + " (set a larger 'voxel')");
  progress.start("a tube on a grid");
  vdb::initialise_openvdb();
  const vdb::Frame f = frame_around(segments, voxel);
  std::vector<RoundSegment> cones;
  cones.reserve(segments.size());
  for (const RoundSegment& c : segments) cones.push_back(local(c, f));

  // Each block with the cones whose band reaches it, or marked wholly inside one; sorted by block.
  double most = 0;
  for (const RoundSegment& c : cones) most += blocks_count(c);
  std::vector<Pair> pairs;
  pairs.reserve(static_cast<std::size_t>(most));
  for (std::size_t n = 0; n < cones.size(); ++n) {
    if ((n & 1023) == 1023 && progress.cancelled()) throw Cancelled();
    blocks_near(cones[n], [&](std::int64_t i, std::int64_t j, std::int64_t k) {
      const Vec3 centre{block * i + 3.5, block * j + 3.5, block * k + 3.5};
      const double d = round_cone_distance(cones[n], centre);
      if (d + block_reach < -band)
        pairs.push_back({key_of(i, j, k), inside});
      else if (d - block_reach < band)
        pairs.push_back({key_of(i, j, k), static_cast<std::uint32_t>(n)});
    });
  }
  if (progress.cancelled()) throw Cancelled();
  std::sort(pairs.begin(), pairs.end());  // `inside` last in each block's run

  vdb::Grid::Ptr g = vdb::Grid::create(band);
  g->setGridClass(openvdb::GRID_LEVEL_SET);
  auto access = g->getAccessor();
  std::size_t done = 0;
  std::array<float, block * block * block> values;
  for (std::size_t first = 0, last = 0; first < pairs.size(); first = last) {
    if ((++done & 255) == 0 && progress.cancelled()) throw Cancelled();
    const std::uint64_t key = pairs[first].key;
    while (last < pairs.size() && pairs[last].key == key) ++last;
    if (pairs[last - 1].cone == inside) continue;
    const auto [bi, bj, bk] = block_of(key);
    bool any = false;
    std::size_t v = 0;
    for (int i = 0; i < block; ++i)
      for (int j = 0; j < block; ++j)
        for (int k = 0; k < block; ++k, ++v) {
          const Vec3 p{static_cast<double>(block * bi + i), static_cast<double>(block * bj + j),
                       static_cast<double>(block * bk + k)};
          double d = band;
          for (std::size_t c = first; c < last; ++c) d = std::min(d, round_cone_distance(cones[pairs[c].cone], p));
          values[v] = static_cast<float>(std::max(d, -static_cast<double>(band)));
          any = any || std::abs(values[v]) < band;
        }
    if (!any) continue;  // no surface here: the flood fill signs it
    v = 0;
    for (int i = 0; i < block; ++i)
      for (int j = 0; j < block; ++j)
        for (int k = 0; k < block; ++k, ++v) {
          const openvdb::Coord ijk(static_cast<int>(block * bi + i), static_cast<int>(block * bj + j),
                                   static_cast<int>(block * bk + k));
          if (std::abs(values[v]) < band)
            access.setValue(ijk, values[v]);
          else
            access.setValueOff(ijk, values[v]);
        }
  }
  Mesh solid = vdb::openvdb_call([&] {
    openvdb::tools::signedFloodFill(g->tree());
    // A thousandth of a voxel inside: a surface through lattice points would give the mesher coincident points.
    return vdb::iso_surface(*g, f, -1.0 / 1024, opt.adaptivity);
  });
  if (progress.cancelled()) throw Cancelled();
  const MeshTopology t = mesh_topology(solid, progress);
  if (solid.triangles.empty() || !t.closed())
    throw Error("OpenVDB's mesher did not close the tube at voxel " + number_text(voxel) +
                (solid.triangles.empty() ? " (it is empty)" : ": " + t.first_problem) + "; try another 'voxel'");
  if (!solid.finite()) throw Error("the tube on a grid gave non-finite points");
  return solid;
}

}  // namespace selfsim::print
