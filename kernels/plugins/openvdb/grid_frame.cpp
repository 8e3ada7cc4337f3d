#include "kernels/plugins/openvdb/grid_frame.h"

#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <mutex>

#include "kernels/base/check.h"

namespace selfsim::vdb {

void initialise_openvdb() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

// The frame for `box` at `voxel`, refusing a voxel that is not positive and finite or below 1e-100, or a box
// more than 2^20 voxels across (float coordinates then still resolve 1/16 of a voxel).
Frame frame_for(const BBox3& box, double voxel) {
  if (!(voxel > 0 && std::isfinite(voxel)))
    throw Error("the voxel size (given as 'voxel', or 1/128 of the longest side) must be a positive number, got " +
                number_text(voxel));
  // Areas and volumes in voxels square and cube it: below 1e-100 they would underflow.
  if (voxel < 1e-100)
    throw Error("the voxel size " + number_text(voxel) +
                " is too small for double precision (below 1e-100): scale the shape up");
  const Vec3 s = box.size();
  if (!std::isfinite(std::max({s.x, s.y, s.z})))
    throw Error("the shape's extent overflows double precision (no side may reach about 1.8e308)");
  const double across = std::max({s.x, s.y, s.z}) / voxel;
  if (!(across <= 1 << 20))
    throw Error("at voxel size " + number_text(voxel) + " the shape is " + number_text(across) +
                " voxels across, more than 2^20 (give a larger 'voxel')");
  return {box.min, voxel};
}

// Budget points of the OpenVDB trees a conversion of shapes with these corners and this area holds: the
// band's voxels (16 bytes each with the leaves, `across` voxels across each wall), and the two levels of
// inner nodes (4096 and 128 voxels wide, about 270 and 34 KB each) for every cell of those widths a corner
// falls in or the area covers, three times over for the grids held at once. Scattered small parts each need
// their own inner nodes, which area alone would miss.
double tree_size(const std::vector<Vec3>& corners, double area, const Frame& f, double across) {
  double size = across * area / (f.voxel * f.voxel);
  for (const double width : {4096.0, 128.0}) {
    std::vector<std::array<std::int64_t, 3>> cells;
    cells.reserve(corners.size());
    for (Vec3 p : corners) {
      const Vec3 q = (1 / (width * f.voxel)) * (p - f.origin);
      cells.push_back({static_cast<std::int64_t>(q.x), static_cast<std::int64_t>(q.y), static_cast<std::int64_t>(q.z)});
    }
    std::sort(cells.begin(), cells.end());
    const double distinct = static_cast<double>(std::unique(cells.begin(), cells.end()) - cells.begin());
    const double covered = 2 * area / (width * width * f.voxel * f.voxel);
    size += (distinct + covered) * 3 * (width > 1000 ? 270e3 : 34e3) / 16;
  }
  return size;
}

// m's distance grid in frame f: a level set `band` voxels to each side (or `inside` voxels inside, when given),
// or for an open mesh its unsigned distance.
Grid::Ptr mesh_grid(const Mesh& m, bool closed, const Frame& f, Interrupter& interrupt, float band, float inside) {
  std::vector<openvdb::Vec3s> points;
  points.reserve(m.points.size());
  for (Vec3 p : m.points) points.push_back(f.local(p));
  std::vector<openvdb::Vec3I> triangles;
  triangles.reserve(m.triangles.size());
  for (const Triangle& t : m.triangles) triangles.emplace_back(t[0], t[1], t[2]);
  const auto unit = openvdb::math::Transform::createLinearTransform(1.0);
  Grid::Ptr g =
      !closed ? openvdb::tools::meshToUnsignedDistanceField<Grid>(interrupt, *unit, points, triangles, {}, band)
      : inside > 0
          ? openvdb::tools::meshToSignedDistanceField<Grid>(interrupt, *unit, points, triangles, {}, band, inside)
          : openvdb::tools::meshToLevelSet<Grid>(interrupt, *unit, points, triangles, band);
  if (interrupt.progress.cancelled()) throw Cancelled();
  return g;
}

Mesh iso_surface(const Grid& g, const Frame& f, double isovalue, double adaptivity) {
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(g, points, triangles, quads, isovalue, adaptivity);
  Mesh m;
  m.points.reserve(points.size());
  for (const auto& p : points) m.points.push_back(f.world(p));
  m.triangles.reserve(triangles.size() + 2 * quads.size());
  for (const auto& t : triangles) m.triangles.push_back({t[0], t[1], t[2]});
  for (const auto& q : quads) {
    if (norm(m.points[q[0]] - m.points[q[2]]) <= norm(m.points[q[1]] - m.points[q[3]])) {
      m.triangles.push_back({q[0], q[1], q[2]});
      m.triangles.push_back({q[0], q[2], q[3]});
    } else {
      m.triangles.push_back({q[0], q[1], q[3]});
      m.triangles.push_back({q[1], q[2], q[3]});
    }
  }
  if (enclosed_volume(m) < 0)
    for (Triangle& t : m.triangles) std::swap(t[1], t[2]);
  return m;
}

}  // namespace selfsim::vdb
