// Seed 004's exclusion-radius curve (Bowyer): every segment is split at its midpoint, and the midpoint moves
// along the segment's perpendicular bisector, to whichever side lets it go farther, as far as it can while
// the new point and both new segments keep the exclusion radius from every other part of every curve and
// from the region's boundary (split_reach.h says exactly what is measured, in both modes). The radius is
// multiplied by `factor` at each level. The curves fill the region and never cross or touch.
//
// Order. `breadth`: level after level, every segment of the level split once, each split seeing every split
// before it; curves in the order given (backwards on backward levels), with `alternate` every even level
// scanned backwards (Figure 4: bottom left to top right, then back), with `forward` every level forwards
// (Figure 5). `depth`: each start segment is split, then its first half recursively to the last level,
// then its second half.
//
// Ties. The point goes to the left of the segment (its direction turned 90° counterclockwise) unless the
// right side reaches farther by more than one part in 10^9. A point that can move less than 10^-6 of the
// half segment on both sides stays at the midpoint (the segment still splits) and is counted as stuck.
#pragma once

#include <cstddef>
#include <vector>

#include "kernels/base/budget.h"
#include "kernels/base/progress.h"
#include "kernels/exclusion/level_report.h"
#include "kernels/geom/polyline.h"
#include "kernels/region/region.h"

namespace selfsim::exclusion {

enum class Order { breadth, depth };
enum class Scan { alternate, forward };
enum class Mode { exact, vertex, original };  // original: Bowyer's program point for point (original_rule.h)

struct CurveOptions {
  double radius = 0.1;  // exclusion radius of the first level's splits
  double factor = 0.8;  // radius multiplied by this at each level, in (0, 1]
  int levels = 1;       // levels of splitting, each doubling the segments, in [0, 40]
  Order order = Order::breadth;
  Scan scan = Scan::alternate;
  Mode exclusion = Mode::exact;
  bool brute_force = false;  // measure every segment for every split instead of the grid's neighbours
                             // (benches and tests compare the two)
  PointBudget budget;

  void validate() const;
};

struct CurveResult {
  Polyline curve;                   // one path per start curve (a closed one ends at its first point);
                                    // point field `level` (0: a start point), cell field `curve` (from 1)
  std::vector<LevelReport> levels;  // per level (depth order: per depth)
  std::size_t stuck() const;
};

// Points the result will have: every path's segments doubled `levels` times, plus its ends.
double curve_size(const Polyline& start, int levels);
// Budget units the run needs: its points and, in points' worth, the working memory (segments, grid).
double working_size(const Polyline& start, int levels);

// Grows the start curves (one path each; a path that ends where it starts is closed) inside the region.
// Throws Error for a bad option or start (start_check.h); BudgetError before any work when working_size is
// over the budget; Cancelled.
CurveResult exclusion_curve(const Region& region, const Polyline& start, const CurveOptions& opt, Progress& progress);

}  // namespace selfsim::exclusion
