#include "kernels/print/first_layer.h"

#include <algorithm>
#include <cmath>

namespace selfsim::print {

double first_layer_area(const Mesh& m, double layer) {
  // The lowest point a triangle uses: a point no triangle uses is nothing to stand on.
  const BBox3 box = corner_bbox(m);
  const double z = box.min.z + 0.5 * layer, cx = 0.5 * (box.min.x + box.max.x), cy = 0.5 * (box.min.y + box.max.y);
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
    // About the box's centre: far from the origin (1e9) the terms would cancel to rounding noise.
    twice_area += (p.x - cx) * (q.y - cy) - (q.x - cx) * (p.y - cy);
  }
  return std::abs(0.5 * twice_area);  // a solid facing inwards has its area negative
}

}  // namespace selfsim::print
