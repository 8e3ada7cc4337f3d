// Developing fractal curves (seed 002): the level stack's control mesh (control_mesh.h), smoothed by Loop
// subdivision (loop_subdivision.h) with the stack's four corners kept (the ends of its first and last levels:
// a closed stack, an annulus, has none), so the smooth surface still spans the coarsest and finest curves.
#pragma once

#include <span>

#include "kernels/develop/control_mesh.h"
#include "kernels/develop/loop_subdivision.h"

namespace selfsim::develop {

struct DevelopOptions {
  double height = 1;   // gap between levels l and l+1, in segment lengths of level l
  int smooth = 0;      // rounds of Loop subdivision, in [0, 12]
  PointBudget budget;  // refuse (before subdividing) a result predicted not to fit

  void validate() const;
};

Mesh develop_surface(std::span<const Polyline* const> levels, const DevelopOptions& opt, Progress& progress);

}  // namespace selfsim::develop
