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
//
// The bounded-curvature variant (`bounded`, after C. Loop, "Triangle mesh subdivision with bounded curvature
// and the convex hull property", MSR-TR-2001-24, which seed 002 used): classic Loop's curvature blows up at
// interior points of valence n ≥ 7 — which the dragon's control mesh is full of — because the eigenvalue of
// the second Fourier mode of the ring around such a point, 3/8 + cos(4π/n)/4, exceeds the square of the
// subdominant one, L = 3/8 + cos(2π/n)/4. Around those points we replace the edge rule by a mask over the
// whole ring (our derivation in Loop's manner, see bounded_edge_mask): the new point on the edge from v to
// ring point i is a·v + Σ_j w_((j−i) mod n)·ring_j with w_k = m(cos 2πk/n)/n, where the mask equation
// m(x) = 8·c3·(x + 1)(x − r)² has the Fourier coefficients 1 − a, L, L², c3 — so the ring's eigenvalues are
// L (kept), L² (bounded curvature) and c3 — and its roots −1, r, r make every weight non-negative:
//   r = (3L − 2)/(2L),  c3 = L³/(4 − 4L),  1 − a = 2L² + L(3L − 2)²/(2(1 − L)),
// and the vertex rule's β = (1 − a − L²)/n keeps the other eigenvalue of the constant mode at L². At n = 6
// this is exactly the regular rule (a = 3/8, w = 3/8, 1/8, 0, …). Points of valence ≤ 6 and boundaries keep
// the classic rules (their curvature is bounded already). An edge between two such points averages both.
#pragma once

#include <cstdint>
#include <vector>

#include "kernels/base/budget.h"
#include "kernels/base/progress.h"
#include "kernels/geom/mesh.h"

namespace selfsim::develop {

struct LoopOptions {
  int steps = 1;                       // rounds of subdivision, in [0, 12]
  std::vector<std::uint32_t> corners;  // boundary points kept where they are
  PointBudget budget;                  // refuse (before any work) a result predicted not to fit: points plus triangles
  bool bounded = false;                // the bounded-curvature rules around interior points of valence ≥ 7

  void validate() const;
};

// Points plus triangles after `steps` rounds, from the closed forms V' = V + E, E' = 2E + 3F, F' = 4F.
double loop_size(const Mesh& m, int steps);

// m subdivided. Throws Error if m is not a manifold (naming the first problem), BudgetError when too big.
Mesh loop_subdivide(const Mesh& m, const LoopOptions& opt, Progress& progress);

// The new interior-vertex weight β for valence n (exposed for tests).
double loop_beta(std::size_t valence);

// The bounded variant's rule at an interior point of valence n: the new point on the edge to ring point 0
// is centre·v + Σ_k ring[k]·(ring point k), ring points counted around v; and the vertex rule's β. Below
// valence 7 these are the classic rules.
struct EdgeMask {
  double centre = 0;
  std::vector<double> ring;
};
EdgeMask bounded_edge_mask(std::size_t valence);
double bounded_beta(std::size_t valence);

}  // namespace selfsim::develop
