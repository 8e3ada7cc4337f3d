// The OpenVDB pieces that level_set.cpp (boundaries, .vdb files) and wall_grid.cpp (the walls as a distance
// grid) share: converting volumes to level sets in a local frame. Includes OpenVDB, whose headers take a
// minute to compile: include it only from those two files.
#pragma once

#include <openvdb/openvdb.h>

#include <vector>

#include "kernels/geom/error.h"
#include "kernels/geom/mesh.h"
#include "kernels/geom/progress.h"
#include "kernels/geom/volume.h"

namespace selfsim::vdb {

// OpenVDB's interrupter concept over our Progress: its conversions ask wasInterrupted() as they go.
struct Interrupter {
  Progress& progress;
  void start(const char* = nullptr) {}
  void end() {}
  bool wasInterrupted(int = -1) { return progress.cancelled(); }
};

void initialise_openvdb();

// The surface area of a volume's distinct boxes, spheres and meshes, each of which becomes a level set.
double parts_area(const Volume& v);

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

// The frame for `box` at `voxel`, refusing a voxel that is not positive and finite or below 1e-100, or a box
// more than 2^20 voxels across (float coordinates then still resolve 1/16 of a voxel).
Frame frame_for(const BBox3& box, double voxel);

// Budget points of the OpenVDB trees a conversion of shapes with these corners and this area holds: the
// band's voxels (16 bytes each with the leaves, `across` voxels across each wall), and the two levels of
// inner nodes (4096 and 128 voxels wide, about 270 and 34 KB each) for every cell of those widths a corner
// falls in or the area covers, three times over for the grids held at once. Scattered small parts each need
// their own inner nodes, which area alone would miss.
double tree_size(const std::vector<Vec3>& corners, double area, const Frame& f, double across = 7);

// The corners of a volume's parts: where the level sets' trees grow.
void part_corners(const Volume& v, std::vector<Vec3>& out);

// OpenVDB's own exceptions as one-line errors.
template <class Body>
auto openvdb_call(Body&& body) {
  try {
    return body();
  } catch (const openvdb::Exception& e) {
    throw Error(std::string("OpenVDB: ") + e.what());
  }
}

// The exact boundary of a box, sphere or mesh.
Mesh exact_boundary(const Volume& v, double voxel);

using Grid = openvdb::FloatGrid;

// A mesh's level set (closed) or unsigned distance (open), in frame f with voxel 1, `band` voxels either side.
Grid::Ptr mesh_grid(const Mesh& m, bool closed, const Frame& f, Interrupter& interrupt, float band = 3);

// The level set of any volume in frame f, `band` voxels either side of every part: parts converted, then
// combined in order (nested unions and differences flattened, each distinct part once: combined_parts).
Grid::Ptr volume_level_set(const Volume& v, const Frame& f, Interrupter& interrupt, float band = 3);

}  // namespace selfsim::vdb
