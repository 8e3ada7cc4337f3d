// Distances between points, segments and triangles in 3D, exact to rounding; a segment of zero length is its
// point and a flat triangle its edges. What the contact tests of meshes and the exclusion surfaces (seed
// 004 in 3D) measure with.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "kernels/geom/vec3.h"

namespace selfsim {

// The point of segment a-b nearest p.
inline Vec3 closest_on_segment(Vec3 p, Vec3 a, Vec3 b) {
  const Vec3 d = b - a;
  const double len2 = dot(d, d);
  if (len2 == 0) return a;
  return a + std::clamp(dot(p - a, d) / len2, 0.0, 1.0) * d;
}

// Whether x, a point of the plane of triangle a, b, c with normal n = cross(b - a, c - a), lies in it
// (edges included).
inline bool in_triangle(Vec3 x, Vec3 a, Vec3 b, Vec3 c, Vec3 n) {
  return dot(cross(b - a, x - a), n) >= 0 && dot(cross(c - b, x - b), n) >= 0 && dot(cross(a - c, x - c), n) >= 0;
}

// The point of triangle a, b, c nearest p: p dropped onto the plane when that lands inside, else the nearest
// point of an edge. A triangle whose height is below 1e-12 of its longest edge counts as flat: its edges.
inline Vec3 closest_on_triangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 n = cross(b - a, c - a);
  const double longest = std::max({dot(b - a, b - a), dot(c - b, c - b), dot(a - c, a - c)});
  if (dot(n, n) > 1e-24 * longest * longest) {
    const Vec3 q = p - (dot(p - a, n) / dot(n, n)) * n;
    if (in_triangle(q, a, b, c, n)) return q;
  }
  Vec3 best = a;
  double best2 = std::numeric_limits<double>::infinity();
  for (const auto& [u, v] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
    const Vec3 q = closest_on_segment(p, u, v);
    if (dot(p - q, p - q) < best2) best = q, best2 = dot(p - q, p - q);
  }
  return best;
}

inline double point_segment_distance(Vec3 p, Vec3 a, Vec3 b) { return norm(p - closest_on_segment(p, a, b)); }

inline double point_triangle_distance(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
  return norm(p - closest_on_triangle(p, a, b, c));
}

// Distance between segments a-b and c-d: their nearest interior points when both lie inside (lines not
// within 1e-12 radians of parallel), else the nearest of an end to the other segment.
inline double segment_segment_distance(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  double best = std::min({point_segment_distance(a, c, d), point_segment_distance(b, c, d),
                          point_segment_distance(c, a, b), point_segment_distance(d, a, b)});
  const Vec3 d1 = b - a, d2 = d - c, n = cross(d1, d2);
  const double nn = dot(n, n);
  if (nn > 1e-24 * dot(d1, d1) * dot(d2, d2)) {
    const Vec3 w = c - a;
    const double s = dot(cross(w, d2), n) / nn, t = dot(cross(w, d1), n) / nn;
    if (s >= 0 && s <= 1 && t >= 0 && t <= 1) best = std::min(best, norm((a + s * d1) - (c + t * d2)));
  }
  return best;
}

// Distance between triangles a and b that do not cross: the least of each corner's distance to the other
// triangle and of the edges' distances to each other.
inline double triangle_distance(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b) {
  double best = INFINITY;
  for (int k = 0; k < 3; ++k) {
    best = std::min(
        {best, point_triangle_distance(a[k], b[0], b[1], b[2]), point_triangle_distance(b[k], a[0], a[1], a[2])});
    for (int j = 0; j < 3; ++j)
      best = std::min(best, segment_segment_distance(a[k], a[(k + 1) % 3], b[j], b[(j + 1) % 3]));
  }
  return best;
}

}  // namespace selfsim
