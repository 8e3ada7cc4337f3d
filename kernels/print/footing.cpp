#include "kernels/print/footing.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "kernels/geom/vec2.h"

namespace selfsim::print {

namespace {

double turn(Vec2 o, Vec2 a, Vec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

// The convex hull, counter-clockwise (Andrew's monotone chain); 1 or 2 points when they are all in a line.
std::vector<Vec2> hull(std::vector<Vec2> p) {
  std::sort(p.begin(), p.end(), [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  p.erase(std::unique(p.begin(), p.end(), [](Vec2 a, Vec2 b) { return a.x == b.x && a.y == b.y; }), p.end());
  if (p.size() < 3) return p;
  std::vector<Vec2> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && turn(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && turn(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

double distance_to_segment(Vec2 c, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = ab.x * ab.x + ab.y * ab.y;
  const double s = len2 > 0 ? std::clamp(((c.x - a.x) * ab.x + (c.y - a.y) * ab.y) / len2, 0.0, 1.0) : 0.0;
  return norm(c - (a + s * ab));
}

}  // namespace

Vec3 mass_centre(const Mesh& m) {
  const BBox3 box = corner_bbox(m);
  if (box.empty()) return {};
  const Vec3 o = 0.5 * (box.min + box.max);
  double volume = 0;
  Vec3 moment{};
  for (const Triangle& t : m.triangles) {
    const double v = volume_term(m, t, o);  // a tetrahedron from o, its centroid a quarter of the way
    volume += v;
    moment += (v / 4) * (m.points[t[0]] + m.points[t[1]] + m.points[t[2]] - 3 * o);
  }
  const double size = norm(box.size());
  if (!(std::abs(volume) > 1e-12 * size * size * size)) return o;
  return o + moment / volume;
}

bool centre_over_footprint(const Mesh& m, Vec3 centre, double contact, double margin) {
  double lowest = std::numeric_limits<double>::infinity();
  for (const Triangle& t : m.triangles)
    for (std::uint32_t v : t) lowest = std::min(lowest, m.points[v].z);
  std::vector<Vec2> touching;
  for (const Triangle& t : m.triangles)
    for (std::uint32_t v : t)
      if (m.points[v].z - lowest <= contact) touching.push_back({m.points[v].x, m.points[v].y});
  const std::vector<Vec2> h = hull(std::move(touching));
  const Vec2 c{centre.x, centre.y};
  if (h.empty()) return false;
  if (h.size() == 1) return norm(c - h[0]) <= margin;
  if (h.size() == 2) return distance_to_segment(c, h[0], h[1]) <= margin;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const Vec2 a = h[i], b = h[(i + 1) % h.size()];
    if (turn(a, b, c) < -margin * norm(b - a)) return false;  // outside this edge by more than the margin
  }
  return true;
}

}  // namespace selfsim::print
