// Curve hoisting (seed 000 §2.1, Equation 1): redrawing a path Q in the moving frame of a smooth curve P,
//   H(t) = P(qx(t)) + qy(t) · N(qx(t)),
// the x of each point of Q read as a fraction of P's arclength and its y as an offset along P's normal N.
// The reference segment (0,0)–(1,0) hoisted onto P gives P; points of Q with x outside [0, 1] reach P's
// boundary extension (base_curve.h).
#pragma once

#include "kernels/base/progress.h"
#include "kernels/geom/polyline.h"
#include "kernels/hoist/base_curve.h"

namespace selfsim::hoist {

// Q hoisted onto P (in place: pass Q moved when it is not needed again): one point per point of Q, Q's
// paths and fields kept. Threads work on fixed chunks of
// points, so the result does not depend on the thread count. Throws Error if a point comes out non-finite.
Polyline hoist_onto(Polyline q, const BaseCurve& p, Boundary boundary, Progress& progress);

}  // namespace selfsim::hoist
