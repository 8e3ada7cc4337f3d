#include "kernels/geom/openvdb_grid.h"

#include <openvdb/tools/Composite.h>
#include <openvdb/tools/MeshToVolume.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <mutex>
#include <numbers>

#include "kernels/geom/box_mesh.h"
#include "kernels/geom/check.h"

namespace selfsim::vdb {

void initialise_openvdb() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

double parts_area(const Volume& v) {
  double a = 0;
  for (const Volume* p : volume_leaves(v)) {
    switch (p->kind) {
      case Volume::Kind::box: {
        const Vec3 s = p->hi - p->lo;
        a += 2 * (s.x * s.y + s.y * s.z + s.z * s.x);
        break;
      }
      case Volume::Kind::sphere:
        a += 4 * std::numbers::pi * p->radius * p->radius;
        break;
      default:
        a += surface_area(*p->mesh);
    }
  }
  return a;
}

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

Mesh exact_boundary(const Volume& v, double voxel) {
  switch (v.kind) {
    case Volume::Kind::box:
      return box_mesh(v.lo, v.hi);
    case Volume::Kind::sphere:
      return sphere_mesh(v.centre, v.radius, voxel / 4);
    default:
      return *v.mesh;
  }
}

Grid::Ptr mesh_grid(const Mesh& m, bool closed, const Frame& f, Interrupter& interrupt, float band) {
  std::vector<openvdb::Vec3s> points;
  points.reserve(m.points.size());
  for (Vec3 p : m.points) points.push_back(f.local(p));
  std::vector<openvdb::Vec3I> triangles;
  triangles.reserve(m.triangles.size());
  for (const Triangle& t : m.triangles) triangles.emplace_back(t[0], t[1], t[2]);
  const auto unit = openvdb::math::Transform::createLinearTransform(1.0);
  Grid::Ptr g = closed
                    ? openvdb::tools::meshToLevelSet<Grid>(interrupt, *unit, points, triangles, band)
                    : openvdb::tools::meshToUnsignedDistanceField<Grid>(interrupt, *unit, points, triangles, {}, band);
  if (interrupt.progress.cancelled()) throw Cancelled();
  return g;
}

Grid::Ptr volume_level_set(const Volume& v, const Frame& f, Interrupter& interrupt, float band) {
  if (v.exact()) return mesh_grid(exact_boundary(v, f.voxel), true, f, interrupt, band);
  const std::vector<const Volume*> parts = combined_parts(v);
  Grid::Ptr result = volume_level_set(*parts[0], f, interrupt, band);
  for (std::size_t i = 1; i < parts.size(); ++i) {
    Grid::Ptr next = volume_level_set(*parts[i], f, interrupt, band);
    if (v.kind == Volume::Kind::unite)
      openvdb::tools::csgUnion(*result, *next);
    else
      openvdb::tools::csgDifference(*result, *next);
  }
  return result;
}

void part_corners(const Volume& v, std::vector<Vec3>& out) {
  for (const Volume* p : volume_leaves(v)) {
    if (p->kind == Volume::Kind::mesh) {
      out.insert(out.end(), p->mesh->points.begin(), p->mesh->points.end());
    } else {
      const BBox3 b = p->bbox();
      for (int k = 0; k < 8; ++k)
        out.push_back({k & 1 ? b.max.x : b.min.x, k & 2 ? b.max.y : b.min.y, k & 4 ? b.max.z : b.min.z});
    }
  }
}

}  // namespace selfsim::vdb
