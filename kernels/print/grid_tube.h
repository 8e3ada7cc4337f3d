// Tubes on a distance grid (issue 25): every point within `radius` of a curve — the union of round-ended
// capsules around its segments — meshed by OpenVDB as thicken_on_grid meshes a thickened sheet (grid_thicken.h),
// the segments given to it as degenerate triangles (a, b, b), whose distance is the segment's. Unlike the
// mitred tube (tube.h), any turn works (an exclusion curve's 170-degree zigzags), branches and paths that meet
// merge into one solid (a plant), and ends are round. Detail below a voxel is lost. 2D curves lie in z = 0.
//
// A radius per point (issue 40: a plant's `width`, tapering to its tips) makes each segment a round cone
// (round_cone.h), the hull of the balls at its ends: the plugin samples the union's signed distance on a
// narrow band of voxels near the cones (round_tube_on_grid) and meshes it.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "kernels/base/budget.h"
#include "kernels/base/progress.h"
#include "kernels/geom/mesh.h"
#include "kernels/geom/point_text.h"
#include "kernels/geom/polyline.h"
#include "kernels/print/round_cone.h"

namespace selfsim::print {

struct GridTubeOptions {
  double radius = 0;      // > 0 (mm)
  double voxel = 0;       // the grid's, at most half the (thinnest) radius; 0 for a quarter of it
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

// With a radius per point of c (radii[i] > 0 at point i; opt.radius is not used): the union of the round
// cones of its segments. All radii equal: the tube above.
Mesh grid_tube(const Polyline3& c, std::span<const double> radii, const GridTubeOptions& opt, Progress& progress);
Mesh grid_tube(const Polyline& c, std::span<const double> radii, const GridTubeOptions& opt, Progress& progress);

// The voxel such a tube is built at: opt.voxel when given (positive, at most half the thinnest radius), else a
// quarter of the thinnest radius, coarsened by steps of 1.25 while the tube would not fit the budget (down
// to a quarter of the largest radius; past it the build is refused). Its round cones are counted before any
// is made: a voxel at which their list alone would not fit is passed over without making it.
double grid_tube_voxel(const Polyline3& c, std::span<const double> radii, const GridTubeOptions& opt);
double grid_tube_voxel(const Polyline& c, std::span<const double> radii, const GridTubeOptions& opt);

// A voxel in a message: "0.13 mm", and below a hundredth of a millimetre two significant digits ("0.0012 mm").
inline std::string voxel_text(double voxel) { return voxel >= 0.01 ? mm_text(voxel) : short_number(voxel, 2) + " mm"; }

// The OpenVDB plugin's part (round_tube.cpp). Budget points the union of round cones takes at `voxel`:
// `segments` (the caller's) and the plugin's copy of them, the narrow band's voxels and nodes, the list of
// (block, cone) pairs, and the meshed surface.
double round_tube_size(const std::vector<RoundSegment>& segments, double voxel);
// The union's closed surface at opt.voxel (> 0). Throws BudgetError over the budget, Error when the mesher
// does not close it, Cancelled on a stop.
Mesh round_tube_on_grid(const std::vector<RoundSegment>& segments, const GridTubeOptions& opt, Progress& progress);

}  // namespace selfsim::print
