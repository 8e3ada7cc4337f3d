// A round cone: the convex hull of two balls (a, ra) and (b, rb), the piece of a tube whose radius changes
// along a segment (grid_tube.h). Its distance, not the segment's distance less one radius: that would be a
// capsule of one radius, with a step where the next segment's radius starts.
//
// In the plane of the axis and the point, the hull's side is the line touching both circles; with
// s = (ra - rb) / L (the sine of its slope) and c its cosine, the side's outward normal is (s, c) in (axial,
// radial) coordinates, it touches ball a at axial position ra s and ball b at L + rb s. A point whose
// projection along the side falls before the first touch is nearest ball a, after the second ball b, and
// otherwise the side. Exact outside and near the surface on both sides; deeper inside it bounds the depth.
// The union of round cones along a path with radii interpolated linearly is the union of the balls swept
// along it, so a segment split in pieces is the same solid.
#pragma once

#include <algorithm>
#include <cmath>

#include "kernels/geom/vec3.h"

namespace selfsim::print {

struct RoundSegment {
  Vec3 a, b;              // the ends
  double ra = 0, rb = 0;  // the radius at each, >= 0
};

// The signed distance from p to the round cone's surface: negative inside.
inline double round_cone_distance(const RoundSegment& s, Vec3 p) {
  const Vec3 axis = s.b - s.a;
  const double length = norm(axis);
  // One ball inside the other (or a point): the bigger ball is the hull.
  if (length <= std::abs(s.ra - s.rb))
    return s.ra >= s.rb ? std::sqrt(dot(p - s.a, p - s.a)) - s.ra : std::sqrt(dot(p - s.b, p - s.b)) - s.rb;
  const Vec3 u = (1 / length) * axis;
  const Vec3 q = p - s.a;
  const double x = dot(q, u);                                    // along the axis
  const double y = std::sqrt(std::max(0.0, dot(q, q) - x * x));  // from it
  const double sine = (s.ra - s.rb) / length, cosine = std::sqrt(1 - sine * sine);
  const double along = x * cosine - y * sine;  // along the side, 0 where it touches ball a
  if (along < 0) return std::sqrt(dot(q, q)) - s.ra;
  if (along > length * cosine) return std::sqrt(dot(p - s.b, p - s.b)) - s.rb;
  return x * sine + y * cosine - s.ra;
}

}  // namespace selfsim::print
