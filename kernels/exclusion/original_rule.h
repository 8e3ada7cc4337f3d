// Seed 004's exclusion-radius curve by the rule of Bowyer's own 2004 program, point for point (issue 21):
// his published results files (Figure 3's conditions; count, length, sum of squares, longest, shortest)
// come out to every printed digit, levels 0 to 15 for factors 0.6 to 0.95, to 13 for 0.5 and to 12 for
// 0.3 (beyond, his 2004 build's extended precision shows at radii near rounding). original_split.h gives
// one split's rule; this runs his level loop:
//
// - Level by level (breadth first), each level splitting every segment that existed at its start once, in
//   place: each new point and its two segments are obstacles for every later split. The curves are taken
//   in the order given on every level; `alternate` walks each curve backwards (last segment first, a
//   closed curve from its closing segment) on even levels, `forward` never.
// - The radius is multiplied by `factor` after each *curve* of a level, as his program does: with one
//   curve, level N splits with radius·factor^(N−1); with k curves, curve j (from 0) at level N with
//   radius·factor^(k(N−1)+j).
// - Obstacles are every point and segment of every curve and of the region's rings (his boundary chain),
//   except the split segment's first point and the segment itself, and its last point as a vertex. His
//   program measures all of them for every split; with `brute_force` so does this, otherwise a grid finds
//   exactly the same limits (original_grid.h says why), bit for bit.
// - Nothing stops a split: a point that cannot move stays at the midpoint (counted as stuck) and the
//   segment still splits, so every level doubles the segments. The rule is his, not selfsim's exact one:
//   it is conservative in places and leaky in others, so the curve may come closer than the radius to
//   itself or the boundary, and in principle cross them.
//
// Coordinates are scaled by a power of two to a largest coordinate of about 1 (bit for bit the same
// arithmetic, without underflow or overflow) but not moved, as his program never moves them.
#pragma once

#include "kernels/exclusion/exclusion_curve.h"

namespace selfsim::exclusion {

// The same result as exclusion_curve's: one path per start curve (a closed one ends at its first point,
// start points exactly as given), point field `level` (0 for start points), cell field `curve` (from 1),
// one report per level. Reads radius, factor, levels, scan, brute_force and budget from `opt`; order
// must be breadth (Error otherwise), `exclusion` is not read. Throws Error for a bad option or start
// (start_check.h), BudgetError before any work, Cancelled, and Error if a side of a split is never
// stopped (only possible once the curve has left the region).
CurveResult original_curve(const Region& region, const Polyline& start, const CurveOptions& opt, Progress& progress);

}  // namespace selfsim::exclusion
