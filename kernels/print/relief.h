// Reliefs for 3D printing (issue 25): the even-odd region of closed 2D curves (as an SVG fill with
// fill-rule="evenodd" paints a curve or a group: outlines, holes in them, islands in the holes) extruded
// into a solid of a given height, optionally standing on a rectangular base plate.
//
// Without a plate the solid runs from z = 0 to z = height: a bottom cap (the region's triangles turned
// over), a top cap, and side walls of two triangles per boundary segment; one closed, outward-oriented
// component per outline (an island is a component of its own), of genus the outline's number of holes.
// With a plate (base > 0) the result is ONE closed solid: a box from z = −base to 0 under the region's
// bounding box grown by `margin` on every side, and the region standing on it from 0 to height. The plate's
// top face is the rectangle with the region's outlines as holes (their islands-in-holes sit on it too), and
// the walls meet it along the outlines, so no face lies inside the solid.
//
// Fields: point field `height` (float64, the point's z); face field `part` (int32: 0 the plate, or the
// bottom cap when there is no plate; 1 the top; 2 the walls).
#pragma once

#include "kernels/base/budget.h"
#include "kernels/base/progress.h"
#include "kernels/geom/mesh.h"
#include "kernels/geom/polyline.h"

namespace selfsim::print {

struct ReliefOptions {
  double height = 0;   // the region's height above z = 0, in the curve's units; must be > 0
  double base = 0;     // thickness of the base plate below z = 0; 0: no plate
  double margin = 0;   // how far the plate reaches beyond the region's bounding box; > 0 when base > 0
  PointBudget budget;  // refuse (before any work) reliefs predicted not to fit

  // Throws Error naming the option: height not a positive finite number, base or margin negative or not
  // finite, a plate without a margin (the outlines would touch the plate's edge).
  void validate() const;
};

// Points plus triangles of the relief of c, predicted from its point and path counts before any work (an
// upper bound: repeated points are dropped later). What relief() checks against opt.budget.
double relief_size(const Polyline& c, const ReliefOptions& opt);

// The relief of c's even-odd region. Every path of c must be closed (closed_path in polyline.h), simple and
// apart from the others (see region_triangles.h). Throws Error, one line: "a relief needs closed curves:
// path 2 is open (it ends at (x, y), not at its start)", a crossing naming the paths and points, an option
// out of range, or a height (or base) absurd beside the region's size (its bounding box's larger side):
// above 1e6 times it or below 1e-9 of it; BudgetError over opt.budget. O(n log n) in c's points.
Mesh relief(const Polyline& c, const ReliefOptions& opt, Progress& progress = no_progress());

}  // namespace selfsim::print
