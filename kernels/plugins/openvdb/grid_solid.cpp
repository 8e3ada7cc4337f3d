// Solids on OpenVDB grids for printing (grid_thicken.h): a surface thickened as the iso-surface of its
// unsigned distance.
#include <openvdb/openvdb.h>

#include <cmath>
#include <string>

#include "kernels/base/budget.h"
#include "kernels/base/check.h"
#include "kernels/geom/mesh_check.h"
#include "kernels/plugins/openvdb/grid_frame.h"
#include "kernels/print/grid_thicken.h"

namespace selfsim::print {

namespace {

// The frame around m grown by half the thickness and two voxels, so the solid lies inside it.
vdb::Frame frame_around(const Mesh& m, const GridThickenOptions& opt) {
  const double margin = opt.thickness / 2 + 2 * opt.voxel_size();
  BBox3 box = m.bbox();
  box.min = box.min - Vec3{margin, margin, margin};
  box.max = box.max + Vec3{margin, margin, margin};
  return vdb::frame_for(box, opt.voxel_size());
}

// Voxels of band each side of the surface: past half the thickness, by two (the mesher reads around it).
float band_of(const GridThickenOptions& opt) {
  return static_cast<float>(std::ceil(opt.thickness / 2 / opt.voxel_size()) + 2);
}

}  // namespace

double grid_thicken_size(const Mesh& m, const GridThickenOptions& opt) {
  opt.validate();
  const vdb::Frame f = frame_around(m, opt);
  // The band on both sides of the surface, and the solid: two sheets of the surface's area at the voxel's
  // spacing (points and twice as many triangles).
  const double area = opt.area > 0 ? opt.area : surface_area(m);
  return vdb::tree_size(m.points, area, f, 2 * band_of(opt)) + 2 * 3 * area / (f.voxel * f.voxel);
}

Mesh thicken_on_grid(const Mesh& m, const GridThickenOptions& opt, Progress& progress) {
  opt.validate();
  m.validate();
  if (m.triangles.empty()) throw Error("the mesh has no triangles to thicken");
  check_budget(grid_thicken_size(m, opt), opt.budget,
               "thickening on a grid at voxel size " + number_text(opt.voxel_size()) + " (set a larger 'voxel')");
  progress.start("thickening on a grid");
  vdb::initialise_openvdb();
  vdb::Interrupter interrupt{progress};
  const vdb::Frame f = frame_around(m, opt);
  Mesh solid = vdb::openvdb_call([&] {
    const vdb::Grid::Ptr distance = vdb::mesh_grid(m, false, f, interrupt, band_of(opt));
    if (progress.cancelled()) throw Cancelled();
    // A thousandth of a voxel inside half the thickness: a surface lying on the lattice (a sheet or a
    // curve in a coordinate plane, at the default voxel a whole number of voxels from it) would put samples
    // exactly on the iso value, where the mesher makes coincident points and folded triangles.
    return vdb::iso_surface(*distance, f, opt.thickness / 2 / f.voxel - 1.0 / 1024, opt.adaptivity);
  });
  if (progress.cancelled()) throw Cancelled();
  const MeshTopology t = mesh_topology(solid, progress);
  if (solid.triangles.empty() || !t.closed())
    throw Error(
        "OpenVDB's mesher did not close the thickened solid at voxel " + number_text(f.voxel) +
        (solid.triangles.empty() ? " (it is empty: the thickness is below the voxel)" : ": " + t.first_problem) +
        "; try another 'voxel'");
  if (!solid.finite()) throw Error("thickening on a grid gave non-finite points");
  return solid;
}

}  // namespace selfsim::print
