// Tubes around curves for 3D printing (issue 25): a closed, manifold, outward-oriented triangle mesh around
// every path of a 2D or 3D curve (exclusion curves, plants, hoisted and L-system curves), its radius given
// per point (constant, or thinner with level: the binding computes the radii from `radius` and fields).
//
// Shape. Each point of a path gets a ring of `sides` points in the plane that bisects its two segments'
// directions (a mitred joint), so the walls between two rings are straight; the ring is stretched in the
// bend direction by 1/cos(half the turning angle) so the wall stays at the point's radius from the axis.
// The rings' angular origin follows the path by parallel transport (rotation-minimising: one reflection per
// joint, the second reflection of the double reflection method being the identity on a frame vector), so
// the tube does not twist. A closed path (its last point on its first, to a billionth of its size, the rule
// of selfsim::closed_path) becomes a torus with no caps; the transported frame's holonomy (the angle it
// comes back rotated by) is spread evenly over the path's segments. An open path gets a flat cap at each end,
// a fan around a centre point. A 2D curve lies in z = 0, with ring point 0 in that plane.
//
// Layout, path after path: ring i of a path (its point i) is points [base + i * sides, base + (i + 1) *
// sides), ring point k at angle 2 pi k / sides from the frame, counter-clockwise about the path's direction;
// an open path's start and end cap centres follow its rings. Triangles: each segment's wall (2 * sides,
// segment after segment), then an open path's start cap (sides) and end cap (sides). A closed path's last
// point has no ring of its own: its first ring closes the loop.
//
// Fields: every ring point (and cap centre) carries its curve point's point fields; every triangle its
// path's cell fields; added are the face field `path` (int, 0-based) and the point field `radius`.
//
// Refused (selfsim::Error, one line naming the path and point counted from 1 and the coordinates): a radius
// <= 0 or not finite, two consecutive equal points (the caller decides what duplicates mean), a path of one
// point, a turn sharper than 170 degrees (the mitre would explode), a bend whose ring would fold (radius *
// tan(half the turn) longer than half an adjacent segment), and a finished tube that meets itself or another
// path's tube (found with selfsim::first_intersection).
#pragma once

#include <span>

#include "kernels/base/budget.h"
#include "kernels/base/progress.h"
#include "kernels/geom/mesh.h"
#include "kernels/geom/polyline.h"

namespace selfsim::print {

struct TubeOptions {
  int sides = 16;  // points on each ring, in [3, 256]
  PointBudget budget;

  // Throws Error "option 'sides' must be an integer in [3, 256], got N".
  void validate() const;
};

// The tube around every path of c; radii has one radius per point of c. Checks the budget before allocating,
// steps progress every 65,536 points of the tube and while it looks for self-intersections (throws Cancelled).
Mesh tube(const Polyline3& c, std::span<const double> radii, const TubeOptions& opt, Progress& progress);
// The same around a 2D curve lying in z = 0.
Mesh tube(const Polyline& c, std::span<const double> radii, const TubeOptions& opt, Progress& progress);

// Points plus triangles tube() would make, in O(paths) before any work: what check_budget weighs.
double tube_size(const Polyline3& c, const TubeOptions& opt);
double tube_size(const Polyline& c, const TubeOptions& opt);

// selfsim::closed_path's rule in 3D: a path of at least three points whose last point is its first, to a
// billionth of the diagonal of its bounding box.
bool closed_path3(std::span<const Vec3> path);

}  // namespace selfsim::print
