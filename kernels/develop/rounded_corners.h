// Rounded corners (seed 002 §1, Figures 2 and 4): every corner of a polyline replaced by the circular arc
// tangent to its two segments at half the shorter one's length from the corner, so the rounding radius
// follows the segment length and the curves of successive levels stay locally alike. Where the segments are
// equally long (the dragon's, the terdragon's) the arcs meet at the segment midpoints and the path is a union
// of arcs, other than at an open path's ends, as the paper's figures are. Route 2 of develop
// (bezier_surface.h) smooths each level with cubic Bezier approximations of these same arcs; this is the
// exact curve, for drawing the levels in 2D.
#pragma once

#include "kernels/base/budget.h"
#include "kernels/base/progress.h"
#include "kernels/geom/polyline.h"

namespace selfsim::develop {

struct RoundOptions {
  int samples = 8;     // segments per quarter turn of arc (at least one per arc), in [1, 1024]
  PointBudget budget;  // refuse (before allocating) a result predicted not to fit

  void validate() const;
};

// Points the rounded curve of c will have at most, before any work.
double rounded_size(const Polyline& c, const RoundOptions& opt);

// c with every corner rounded, path by path (a path that ends where it starts is a loop: its first corner too).
// A straight-through corner keeps its point; a U-turn, whose arc would have no radius, too. Uniform point
// fields and the cell fields are kept. Throws Error naming a zero-length segment.
Polyline rounded_corners(const Polyline& c, const RoundOptions& opt, Progress& progress);

}  // namespace selfsim::develop
