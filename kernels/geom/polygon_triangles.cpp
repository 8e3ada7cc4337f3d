#include "kernels/geom/polygon_triangles.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "kernels/base/error.h"
#include "kernels/geom/vec2.h"

namespace selfsim {

namespace {

// Twice the signed area of triangle a, b, c (positive when it turns left).
double turn(Vec2 a, Vec2 b, Vec2 c) { return cross(b - a, c - a); }

// True when p lies inside triangle a, b, c (counterclockwise) or on its edges.
bool inside(Vec2 p, Vec2 a, Vec2 b, Vec2 c) { return turn(a, b, p) >= 0 && turn(b, c, p) >= 0 && turn(c, a, p) >= 0; }

// True when segments a-b and c-d share a point (crossing, touching or overlapping).
bool meet(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double d1 = turn(a, b, c), d2 = turn(a, b, d), d3 = turn(c, d, a), d4 = turn(c, d, b);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  auto on = [](Vec2 p, Vec2 q, Vec2 r) {  // r on segment p-q, given the three are collinear
    return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= r.y &&
           r.y <= std::max(p.y, q.y);
  };
  return (d1 == 0 && on(a, b, c)) || (d2 == 0 && on(a, b, d)) || (d3 == 0 && on(c, d, a)) || (d4 == 0 && on(c, d, b));
}

}  // namespace

void polygon_triangles(std::span<const Vec3> corners, std::vector<std::array<std::size_t, 3>>& out) {
  const std::size_t n = corners.size();
  if (n < 3) throw Error("a polygon has at least three corners");
  // Newell's normal: the polygon's area vector, whatever its shape.
  Vec3 normal{};
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 p = corners[i], q = corners[(i + 1) % n];
    normal += Vec3{(p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y)};
  }
  const double length = norm(normal);
  if (!(length > 0 && std::isfinite(length))) {  // no area: fanned, as it is (a sliver stays a sliver)
    for (std::size_t k = 1; k + 1 < n; ++k) out.push_back({0, k, k + 1});
    return;
  }
  // The plane's axes: the normal's largest component dropped keeps the shape, turned so it runs counter-
  // clockwise seen along the normal.
  const Vec3 a = std::abs(normal.x) >= std::abs(normal.y) && std::abs(normal.x) >= std::abs(normal.z) ? Vec3{0, 1, 0}
                                                                                                      : Vec3{1, 0, 0};
  const Vec3 u = normalized(cross(a, normal)), v = normalized(cross(normal, u));
  std::vector<Vec2> p(n);
  for (std::size_t i = 0; i < n; ++i) p[i] = {dot(corners[i] - corners[0], u), dot(corners[i] - corners[0], v)};
  // Convex: every corner turns left (or goes straight on) and the turns add up to one turn; a star that
  // winds twice (a pentagram) turns left everywhere too.
  bool convex = true;
  double turning = 0;
  for (std::size_t i = 0; i < n && convex; ++i) {
    const Vec2 e = p[(i + 1) % n] - p[i], f = p[(i + 2) % n] - p[(i + 1) % n];
    convex = cross(e, f) >= 0;
    turning += std::atan2(cross(e, f), dot(e, f));
  }
  convex = convex && std::abs(turning - 2 * std::numbers::pi) < 1e-6;
  if (convex) {
    for (std::size_t k = 1; k + 1 < n; ++k) out.push_back({0, k, k + 1});
    return;
  }
  if (n > max_concave_corners)
    throw Error("a polygon of " + std::to_string(n) + " corners is not convex: at most " +
                std::to_string(max_concave_corners) + " corners are cut into triangles (split it first)");
  // Ears cut from a polygon that crosses or touches itself would overlap: refused (quadratic, as the cutting).
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j)
      if (!(i == 0 && j == n - 1) && meet(p[i], p[i + 1], p[j], p[(j + 1) % n]))
        throw Error("a polygon of " + std::to_string(n) +
                    " corners crosses or touches itself (its edges from corners " + std::to_string(i + 1) + " and " +
                    std::to_string(j + 1) + ")");
  // Ears: a corner turning left whose triangle with its two neighbours holds no other remaining corner is
  // cut off; n - 2 cuts leave the last triangle. A full round without an ear means the polygon crosses itself.
  std::vector<std::size_t> next(n), prev(n);
  for (std::size_t i = 0; i < n; ++i) next[i] = (i + 1) % n, prev[i] = (i + n - 1) % n;
  std::size_t at = 0, left = n, tried = 0;
  while (left > 3) {
    const std::size_t b = prev[at], c = next[at];
    bool ear = turn(p[b], p[at], p[c]) > 0;
    for (std::size_t k = next[c]; ear && k != b; k = next[k])
      ear = !(inside(p[k], p[b], p[at], p[c]) && p[k] != p[b] && p[k] != p[at] && p[k] != p[c]);
    if (ear) {
      out.push_back({b, at, c});
      next[b] = c;
      prev[c] = b;
      --left;
      at = c;
      tried = 0;
    } else if (++tried > left) {
      throw Error("a polygon of " + std::to_string(n) + " corners crosses itself: it has no triangles");
    } else {
      at = next[at];
    }
  }
  out.push_back({prev[at], at, next[at]});
}

}  // namespace selfsim
