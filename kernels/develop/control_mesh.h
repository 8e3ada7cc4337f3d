// Route 1 of seed 002 (§3.2): consecutive levels joined into the minimal triangle mesh, the control mesh that
// Loop subdivision later smooths. Each segment (a, b) of level l and the b segments f_0 … f_b of level l+1
// that replace it form one tile of 1 + b triangles: a fan from a over the first half of the fine segments,
// the triangle (a, f_s, b) with s = ⌊b/2⌋, and a fan from b over the rest. For the dragon (b = 2) that is the
// paper's five-sided tile of three triangles (Figure 8a). The tiles of an open curve's levels make a disk,
// those of closed levels (the Koch snowflake) an annulus; every triangle is oriented the same way.
#pragma once

#include <span>

#include "kernels/base/progress.h"
#include "kernels/geom/mesh.h"
#include "kernels/geom/polyline.h"

namespace selfsim::develop {

struct ControlMeshOptions {
  double height = 1;        // gap between levels l and l+1, in segment lengths of level l (level_stack.h)
  double corner_shift = 0;  // in [0, 0.5]: each level's inner points moved this fraction of the way to the
                            // midpoint of their neighbours (§3.2's inward shift against self-intersections)
};

// The control mesh of levels 0..L (at least two), which must refine segment by segment (level_stack.h).
// Points: every level's points at its height (a closed level's repeated end once); point field `level`.
// Faces: (Σ_l<L segments_l)·(1 + b) triangles; face fields `level` (of the tile's coarse segment) and `tile`
// (tiles numbered from 0, level by level, segment by segment). Throws Error naming what does not fit.
Mesh control_mesh(std::span<const Polyline* const> levels, const ControlMeshOptions& opt, Progress& progress);

}  // namespace selfsim::develop
