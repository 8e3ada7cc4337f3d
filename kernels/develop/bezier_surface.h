// Route 2 of seed 002 (§3.1, "direct parameterisation"): a smooth surface f(s, t) through the levels of a
// curve's construction, for curves whose levels do not refine segment by segment (the Hilbert curve) as well
// as those that do. Each level i becomes a smooth curve c_i(t), t ∈ [0, 1]: cubic Bezier pieces between the
// midpoints of its segments (and its two ends, when open), each approximating the circular arc tangent to the
// two segments at their midpoints. The levels are then joined in s ∈ [0, 1] (level i at s = i/L, height z_i)
// by cubic Hermite curves for each t, and f is sampled into a triangle mesh whose rows grow finer with s.
//
// Scaling in s: band i (levels i and i+1) is parameterised by σ = L·s − i ∈ [0, 1], and the tangents are
// derivatives with respect to σ: (c_{i+1} − c_i)/2 at an inner level i (half the next band's chord, with
// its drop in z), (0, 0, −g/2) at the first and last levels, g being the gap to the adjacent level. Every
// band spans the same 1/L of s, so the surface is C¹ in s across the levels (∂f/∂s = L·∂f/∂σ).
#pragma once

#include <cstdint>
#include <span>

#include "kernels/base/budget.h"
#include "kernels/base/progress.h"
#include "kernels/geom/mesh.h"
#include "kernels/geom/polyline.h"

namespace selfsim::develop {

struct BezierOptions {
  double height = 1;   // gap between levels i and i+1, in segment lengths of level i (level_stack.h)
  int resolution = 4;  // samples per Bezier piece of a row's level, in [1, 64]
  PointBudget budget;  // refuse (before any work) a result predicted not to fit: points plus triangles

  void validate() const;
};

// Points plus triangles of bezier_surface's mesh, exactly, from the levels' segment counts and mean segment
// lengths (which set the rows per band), before any work. With R = resolution, a level of n segments has
// P = n + 1 Bezier pieces when open, n when closed, and its rows have R·P intervals (R·P + 1 samples when
// open, R·P when closed). Band i has m_i = max(2, ⌈R·(z_i − z_{i+1}) / ℓ_{i+1}⌉) row steps (ℓ the mean
// segment length): rows about as far apart vertically as the samples of level i+1 are along it. The row at
// level 0 samples level 0; every other row of band i (its inner rows and the row at level i+1) samples
// level i+1. Two consecutive rows of I and I' intervals are joined by I + I' triangles.
double bezier_size(std::span<const Polyline* const> levels, const BezierOptions& opt);

// The same count split up, with the edges on the mesh's boundary (what thickening adds a rim along): the
// first and last rows' intervals, and for open levels both sides' row steps.
struct BezierCounts {
  double points = 0, triangles = 0, boundary_edges = 0;
};
BezierCounts bezier_counts(std::span<const Polyline* const> levels, const BezierOptions& opt);

// The developing surface of levels 0..L (at least two; one path each, all open or all closed): a disk for
// open levels, an annulus for closed ones, with one row of points exactly on every level's smoothed curve at
// its height. Triangles face as the control mesh's do (control_mesh.h): to the right of the curves' direction
// of travel, ∂f/∂s × ∂f/∂t. Point field `level` (float64: L·s, so level i's row has i); face field `level`
// (int32: the band). Throws Error naming a level with no segment, a zero-length segment, or open levels
// mixed with closed ones; BudgetError (before allocating) when bezier_size is over opt.budget; Cancelled.
Mesh bezier_surface(std::span<const Polyline* const> levels, const BezierOptions& opt, Progress& progress);

// The smoothed curve c(t) of one level (one path; closed when it ends where it starts), for t in [0, 1]:
// t = (j + ½)/n is the midpoint of segment j, t = 0 and 1 are an open level's ends. Exposed for tests.
Vec2 smoothed_level_point(const Polyline& level, double t);

// The triangles joining two rows of samples with increasing parameters `upper` and `lower` (in [0, 1], or
// starting anywhere in a window of length 1 when closed), whose points are upper_first + k and
// lower_first + k: walking both rows by increasing parameter, always advancing the row whose next sample
// comes first. An open strip runs from the rows' first samples to their last; a closed one wraps around.
// Writes (upper.size() + lower.size() − (closed ? 0 : 2)) triangles to `out`, oriented upper, lower, next.
void zip_rows(std::span<const double> upper, std::uint32_t upper_first, std::span<const double> lower,
              std::uint32_t lower_first, bool closed, std::span<Triangle> out);

}  // namespace selfsim::develop
