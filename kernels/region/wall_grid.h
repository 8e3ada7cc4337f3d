// A region's walls as a signed distance grid (OpenVDB, in level_set.cpp): how far inside the walls a point
// lies, read by trilinear interpolation from the grid instead of measured against a boundary mesh made from
// it. The exclusion surface's `walls = "grid"` (issue 23).
//
// What the number means. The grid holds, at voxel centres, the signed distance to the region's boundary as
// OpenVDB meshes it from the volume's level set (the boundary volume_boundary makes: a box's, sphere's (its
// sphere_mesh within a quarter voxel) or mesh's own, a union's or difference's as fine as the voxels; a .vdb
// file's zero surface on its own lattice), measured again from that surface (levelSetRebuild). Such values change by at
// most the distance between their centres, so the interpolated value between them is within sqrt(3)/2 of a voxel of the
// function they sample (the trilinear weights' spread is at most a quarter of a voxel squared along each axis), and
// itself changes by at most sqrt(3) times the distance moved (along each axis its slope is a mean of differences of at
// most one voxel per voxel). So a point whose interpolated clearance is c lies at least c - error() inside.
#pragma once

#include <memory>
#include <span>

#include "kernels/base/budget.h"
#include "kernels/base/progress.h"
#include "kernels/geom/vec3.h"
#include "kernels/region/volume.h"

namespace selfsim {

class WallGrid {
 public:
  // How much the interpolated clearance can change per unit moved.
  static constexpr double slope = 1.7320508075688772;

  // The walls of v at `voxel`, resolved at least `depth` inside them (a point deeper reads as deeper than
  // `depth`, not as its distance) and `outside` outside them (at least 3 voxels). A volume read from a .vdb
  // level set (Volume::samples) is measured on that grid, at its own voxel and lattice, whatever `voxel`
  // says. Throws BudgetError over the budget (size()), Error as volume_boundary does for a voxel size it
  // refuses.
  WallGrid(const Volume& v, double voxel, double depth, const PointBudget& budget, Progress& progress,
           double outside = 0);
  // Budget points the grid takes to build and hold.
  static double size(const Volume& v, double voxel, double depth, double outside = 0);

  // Each point's interpolated distance inside the walls (negative outside), in this view's coordinates.
  // Safe to call from several threads at once.
  void clearances(std::span<const Vec3> points, std::span<double> out) const;
  double clearance(Vec3 p) const;
  // The most the true clearance can fall below the interpolated one, in this view's coordinates.
  double error() const;
  double voxel() const;

  // The same walls seen in coordinates q = scale·(p − centre).
  WallGrid in_frame(Vec3 centre, double scale) const;

 private:
  WallGrid() = default;
  struct Data;
  std::shared_ptr<const Data> data_;
  Vec3 centre_{};
  double scale_ = 1;
};

}  // namespace selfsim
