// Whether a point lies inside a closed triangle mesh: the mesh's winding number around it, the sum of the
// solid angles its triangles subtend (Van Oosterom and Strackee's formula) over 4π. About 1 inside an
// outward-oriented closed mesh, 0 outside, whatever the mesh's shape; O(triangles) per point.
#pragma once

#include <cmath>
#include <numbers>

#include "kernels/geom/mesh.h"

namespace selfsim {

inline double winding_number(const Mesh& m, Vec3 p) {
  double total = 0;
  for (const Triangle& t : m.triangles) {
    const Vec3 a = m.points[t[0]] - p, b = m.points[t[1]] - p, c = m.points[t[2]] - p;
    const double la = norm(a), lb = norm(b), lc = norm(c);
    const double numerator = dot(a, cross(b, c));
    const double denominator = la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb;
    total += 2 * std::atan2(numerator, denominator);
  }
  return total / (4 * std::numbers::pi);
}

}  // namespace selfsim
