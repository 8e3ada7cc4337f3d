// Loop subdivision (C. Loop, 1987; seed 002 §3.2): every triangle split into four by a new point on each
// edge, every point moved to a weighted average of its neighbourhood. The weights (Figure 9 of seed 002):
//   old interior point of valence n:  (1 − nβ)·v + β·Σ neighbours,  β = (1/n)·(5/8 − (3/8 + cos(2π/n)/4)²)
//   new point on an interior edge ab with opposite points c, d:  3/8·(a + b) + 1/8·(c + d)
//   old boundary point:  3/4·v + 1/8·(its two boundary neighbours),  new point on a boundary edge:  (a + b)/2
// so boundary curves are refined as cubic B-splines; corners stay where they are: the points the caller names
// (a developing surface's four: the ends of its first and last levels) and any boundary point of a single
// triangle. Old points keep their indices from round to round, so a corner stays one. Every point field is subdivided
// with the same weights (a thickness field with them, as §3.2 says), as float64; faces pass theirs to their four
// children. Each rule's weights sum to 1 (tested).
#pragma once

#include <cstdint>
#include <vector>

#include "kernels/geom/budget.h"
#include "kernels/geom/mesh.h"
#include "kernels/geom/progress.h"

namespace selfsim::develop {

struct LoopOptions {
  int steps = 1;                       // rounds of subdivision, in [0, 12]
  std::vector<std::uint32_t> corners;  // boundary points kept where they are
  PointBudget budget;                  // refuse (before any work) a result predicted not to fit: points plus triangles

  void validate() const;
};

// Points plus triangles after `steps` rounds, from the closed forms V' = V + E, E' = 2E + 3F, F' = 4F.
double loop_size(const Mesh& m, int steps);

// m subdivided. Throws Error if m is not a manifold (naming the first problem), BudgetError when too big.
Mesh loop_subdivide(const Mesh& m, const LoopOptions& opt, Progress& progress);

// The new interior-vertex weight β for valence n (exposed for tests).
double loop_beta(std::size_t valence);

}  // namespace selfsim::develop
