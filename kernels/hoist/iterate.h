// ITERATE of seed 000 §2.2: C starts as P's own samples (an adaptive sampling, §3.1) and each generation
// multiplies C and hoists the result onto P, always onto P:
//   for each generation: C = HOIST(MULTIPLY(C, m), P)
// Multiplicity 1 gives P at every generation.
#pragma once

#include <vector>

#include "kernels/base/budget.h"
#include "kernels/base/progress.h"
#include "kernels/geom/polyline.h"
#include "kernels/geom/segment_transform.h"
#include "kernels/hoist/base_curve.h"

namespace selfsim::hoist {

struct IterateOptions {
  double multiplicity = 3;                   // m, in [1, 1e6]: copies of C per generation
  int generations = 3;                       // rounds of MULTIPLY and HOIST, in [0, 64]
  Boundary boundary = Boundary::Clamp;       // how P extends outside [0, 1] (base_curve.h)
  std::vector<SegmentTransform> transforms;  // copy i of each MULTIPLY takes transforms[i mod size]; empty: Identity
  PointBudget budget;                        // refuse (before any work) results predicted not to fit

  void validate() const;
};

// Points after g generations from a P of n samples: (n − 1)·m^g + 1 (exactly for whole m, about that for a
// non-integer m), with room for the previous generation, which is held while the next is made. Checked
// before any work; each generation's MULTIPLY checks its exact count again before allocating.
double iterated_points(std::size_t n, const IterateOptions& opt);

// The iterated curve: one path from (0,0) to (1,0); point fields `t` (multiply.h) and `generation`
// (uniform). Progress is reported per generation.
Polyline iterate(const Polyline& p, const IterateOptions& opt, Progress& progress);

}  // namespace selfsim::hoist
