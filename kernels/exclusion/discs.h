// The exclusion discs of seed 004's Figure 4: around each point an exclusion curve made at level l >= 1,
// the radius it was made with, radius · factor^(l - 1), drawn as a closed polygon, so that a picture shows
// the room each split kept.
#pragma once

#include "kernels/base/budget.h"
#include "kernels/base/progress.h"
#include "kernels/geom/polyline.h"

namespace selfsim::exclusion {

struct DiscOptions {
  double radius = 0.1;  // the curve's first radius
  double factor = 0.8;  // and its factor
  int level = -1;       // only the points of this level; -1: every level from 1
  int samples = 32;     // polygon corners per disc, in [3, 4096]
  PointBudget budget;
};

// One closed path per disc, cell field `level`. Throws Error when the curve has no `level` point field or
// an option is out of range, BudgetError before any work, Cancelled.
Polyline exclusion_discs(const Polyline& curve, const DiscOptions& opt, Progress& progress);

}  // namespace selfsim::exclusion
