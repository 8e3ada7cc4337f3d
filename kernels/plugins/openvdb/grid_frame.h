// What the OpenVDB plugin's conversions share (internal to kernels/plugins/openvdb): the local frame every
// conversion works in, OpenVDB's interrupter over our Progress, the budget of a conversion's trees, a mesh's
// distance grid and an iso-surface meshed back.
#pragma once

#include <openvdb/openvdb.h>

#include <string>
#include <vector>

#include "kernels/base/error.h"
#include "kernels/base/progress.h"
#include "kernels/geom/bbox.h"
#include "kernels/geom/mesh.h"

namespace selfsim::vdb {

// OpenVDB's interrupter concept over our Progress: its conversions ask wasInterrupted() as they go.
struct Interrupter {
  Progress& progress;
  void start(const char* = nullptr) {}
  void end() {}
  bool wasInterrupted(int = -1) { return progress.cancelled(); }
};

// OpenVDB converts meshes in single precision and indexes voxels with 32-bit integers, and its transforms
// refuse voxels below about 1e-5. So every conversion works in a local frame: coordinates measured from the
// shape's lowest corner in voxels (the grid's own voxel is 1), turned back into the caller's coordinates in
// double precision; a .vdb file's transform gets the real voxel and corner.
struct Frame {
  Vec3 origin;
  double voxel;
  openvdb::Vec3s local(Vec3 p) const {
    const Vec3 q = (1 / voxel) * (p - origin);
    return {static_cast<float>(q.x), static_cast<float>(q.y), static_cast<float>(q.z)};
  }
  Vec3 world(const openvdb::Vec3s& q) const { return origin + voxel * Vec3{q.x(), q.y(), q.z()}; }
};

// OpenVDB's own exceptions as one-line errors.
template <class Body>
auto openvdb_call(Body&& body) {
  try {
    return body();
  } catch (const openvdb::Exception& e) {
    throw Error(std::string("OpenVDB: ") + e.what());
  }
}

using Grid = openvdb::FloatGrid;

void initialise_openvdb();

// The frame for `box` at `voxel`, refusing a voxel that is not positive and finite or below 1e-100, or a box
// more than 2^20 voxels across (float coordinates then still resolve 1/16 of a voxel).
Frame frame_for(const BBox3& box, double voxel);

// Budget points of the OpenVDB trees a conversion of shapes with these corners and this area holds, `across`
// voxels across each wall (see grid_frame.cpp).
double tree_size(const std::vector<Vec3>& corners, double area, const Frame& f, double across = 7);

// m's distance grid in frame f (voxel 1): a level set `band` voxels to each side (or `inside` voxels inside,
// when given), or for an open mesh its unsigned distance `band` voxels out.
Grid::Ptr mesh_grid(const Mesh& m, bool closed, const Frame& f, Interrupter& interrupt, float band = 3,
                    float inside = 0);

// The surface where g (in frame f) equals `isovalue` (in voxels), as triangles facing outwards, each quad
// split along its shorter diagonal; `adaptivity` in [0, 1] merges flat regions' polygons (OpenVDB's).
Mesh iso_surface(const Grid& g, const Frame& f, double isovalue = 0, double adaptivity = 0);
inline Mesh zero_surface(const Grid& g, const Frame& f) { return iso_surface(g, f); }

}  // namespace selfsim::vdb
