// The smooth curve P that paths are hoisted onto (seed 000 §2.1), as the numerical stand-in §3.1 describes: a
// polyline of samples with a unit tangent at each, evaluated at any fraction t of arclength by interpolating
// position and tangent between the two nearest samples (the tangent renormalised). Outside [0, 1], P is
// extended by a boundary mode (seed 000 §2.1, Figure 5): copies of P laid end to end along the x axis, the
// copy over [k, k+1] taken as is for even k and transformed for odd k:
//   repeat     every copy as is (translated)
//   reflect_y  odd copies reflected in the y axis: mirrored left to right, walked backwards
//   reflect_x  odd copies reflected in the x axis: upside down
//   rotate     odd copies turned half a circle: both reflections; the only mode that is tangent continuous
//              at every joint whatever P's end tangents
//   clamp      P continues along the x axis at its own speed: P(t) = (L·t, 0) for t < 0 and
//              (1 + L·(t − 1), 0) for t > 1, L the length of P. (Seed 000 prints (L(t − 1), 0) for t > 1,
//              which would jump back to the origin at t = 1; continuity says it starts from (1, 0).)
#pragma once

#include <vector>

#include "kernels/geom/polyline.h"

namespace selfsim::hoist {

enum class Boundary { Clamp, Repeat, ReflectY, ReflectX, Rotate };

// A point of P and the unit tangent there.
struct Frame {
  Vec2 position;
  Vec2 tangent;

  // The unit normal, 90 degrees counterclockwise from the tangent.
  Vec2 normal() const { return {-tangent.y, tangent.x}; }
};

class BaseCurve {
 public:
  // P: one path from (0,0) to (1,0) of positive length. Its `tangent` point field (2 components, as
  // sample_spline records) gives the tangents at the samples, interpolated between them. Without one, P is
  // a polyline taken as it is: each segment's own direction is the frame along it (so hoisting onto a
  // polyline places Q on every segment as substitution would, corners and U-turns included). Repeated
  // points are skipped. Throws Error naming what is wrong.
  explicit BaseCurve(const Polyline& p);

  // P at fraction t of its arclength, t any finite number, extended outside [0, 1] by `mode`.
  Frame at(double t, Boundary mode) const;
  // Length of P.
  double length() const { return length_; }
  std::size_t samples() const { return points_.size(); }

 private:
  Frame inside(double t) const;  // t in [0, 1]

  std::vector<Vec2> points_, tangents_;  // tangents_ empty: P is a polyline, framed segment by segment
  std::vector<double> t_;                // fraction of arclength at each sample, increasing from 0 to 1
  double length_ = 0;
};

}  // namespace selfsim::hoist
