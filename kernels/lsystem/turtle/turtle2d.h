// The 2D turtle interpretation of an L-system level (seed 002 §1, Table 1), streamed: the level's string is
// never built. rewrite() (rewrite.h) expands depth-first straight into the turtle, and the output is
// reserved from the production-matrix prediction, so memory is the vertex array and nothing more.
// Lattice grammars without branches or moves are drawn by several threads at once (turtle_split.h), each
// into its own slice of the array; the result is byte-identical whatever the number of threads.
#pragma once

#include <optional>

#include "kernels/base/budget.h"
#include "kernels/base/progress.h"
#include "kernels/geom/polyline.h"
#include "kernels/geom/similarity.h"
#include "kernels/lsystem/grammar.h"

namespace selfsim::lsystem {

struct TurtleOptions {
  int level = 0;  // rewriting steps applied to the axiom, in [0, max_level]
  // true: an open curve runs from (0,0) to (1,0); false: every curve stays as the turtle drew it; not given:
  // the grammar decides (a plant stays as drawn, heading up; other open curves are normalised: plant.h).
  std::optional<bool> normalize;
  PointBudget budget;  // refuse (before any work) a level predicted not to fit

  void validate() const;
};

// Where a turtle's drawing in unit steps goes: open curves (turtle ending at `end`, away from its start after
// `steps` unit steps) onto (0,0)-(1,0) when normalizes(g, opt) (plant.h), others scaled by shrink^level.
Similarity2 turtle_placement(const Grammar& g, const TurtleOptions& opt, Vec2 end, double steps);

// The curve of grammar g at opt.level, with a uniform point field `level`.
// Normalisation (unbranched grammars, or normalize = true): when the turtle ends away from where it
// started, the direct similarity taking its start to (0,0) and its end to (1,0) is applied, so every level
// of an open curve spans the same unit segment. A closed curve (turtle back at its start), a plant (plant.h)
// and any curve with normalize = false are left where the turtle drew them: starting at (0,0), heading
// start_heading(), with steps of length shrink^level.
// Branches '[' ']' and move symbols start new paths; a branched grammar's curve also carries the point
// fields `branch_order` (the '[' open when the point was drawn: 0 on the main axis, 1 on its branches, ...;
// a segment's is its end point's) and `root_distance` (along the tree from the start, in the curve's units). Throws
// BudgetError if the level, or the branches it keeps open, would not fit opt.budget; Cancelled when progress says so
// (checked from every thread).
Polyline turtle2d(const Grammar& g, const TurtleOptions& opt, Progress& progress);
// The same into `out`, reusing its memory (for repeated runs; benches).
void turtle2d_into(const Grammar& g, const TurtleOptions& opt, Progress& progress, Polyline& out);

}  // namespace selfsim::lsystem
