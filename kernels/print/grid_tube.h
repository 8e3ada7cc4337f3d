// Tubes on a distance grid (issue 25): every point within `radius` of a curve — the union of round-ended
// capsules around its segments — meshed by OpenVDB as thicken_on_grid meshes a thickened sheet (grid_thicken.h),
// the segments given to it as degenerate triangles (a, b, b), whose distance is the segment's. Unlike the
// mitred tube (tube.h), any turn works (an exclusion curve's 170-degree zigzags), branches and paths that meet
// merge into one solid (a plant), and ends are round. The radius is one for the whole curve; detail below a
// voxel is lost. 2D curves lie in z = 0.
#pragma once

#include "kernels/base/budget.h"
#include "kernels/base/progress.h"
#include "kernels/geom/mesh.h"
#include "kernels/geom/polyline.h"

namespace selfsim::print {

struct GridTubeOptions {
  double radius = 0;      // > 0 (mm)
  double voxel = 0;       // the grid's; 0 for a quarter of the radius
  double adaptivity = 0;  // in [0, 1], OpenVDB's
  PointBudget budget;

  // Throws Error naming the option.
  void validate() const;
  double voxel_size() const { return voxel > 0 ? voxel : radius / 4; }
};

// The closed solid around every path of c. Throws Error for a curve with no segment, BudgetError (predicted
// before any work) over the budget, Error when the mesher does not close the solid, Cancelled on a stop.
Mesh grid_tube(const Polyline3& c, const GridTubeOptions& opt, Progress& progress);
Mesh grid_tube(const Polyline& c, const GridTubeOptions& opt, Progress& progress);

}  // namespace selfsim::print
