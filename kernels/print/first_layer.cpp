#include "kernels/print/first_layer.h"

#include <algorithm>
#include <cmath>

namespace selfsim::print {

double first_layer_area(const Mesh& m, double layer) {
  // The lowest point a triangle uses: a point no triangle uses is nothing to stand on.
  const double z = corner_bbox(m).min.z + 0.5 * layer;
  double twice_area = 0;
  for (const Triangle& t : m.triangles) {
    // The cut: the points where the plane crosses the triangle's edges (a corner exactly on it counts as
    // above, so a plane through a corner cuts each edge at most once and a segment has two ends).
    Vec3 ends[2];
    int n = 0;
    for (int i = 0; i < 3 && n < 2; ++i) {
      const Vec3 a = m.points[t[i]], b = m.points[t[(i + 1) % 3]];
      if ((a.z < z) == (b.z < z)) continue;
      const double s = (z - a.z) / (b.z - a.z);
      ends[n++] = a + s * (b - a);
    }
    if (n < 2) continue;
    const Vec3 normal = area_normal(m, t);
    Vec3 p = ends[0], q = ends[1];
    // Inside on the left: the normal, turned a quarter to the left, runs along the segment.
    if ((q.x - p.x) * -normal.y + (q.y - p.y) * normal.x < 0) std::swap(p, q);
    twice_area += p.x * q.y - q.x * p.y;
  }
  return std::abs(0.5 * twice_area);  // a solid facing inwards has its area negative
}

}  // namespace selfsim::print
