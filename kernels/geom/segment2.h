// Distances and crossings of 2D segments (and a point's to a triangle): what a region's boundary and an
// exclusion curve (seed 004) are measured with, and what bounds an exclusion surface's terms seen along a
// move. Exact to rounding; a segment of zero length is its point.
#pragma once

#include <algorithm>
#include <cmath>

#include "kernels/geom/vec2.h"

namespace selfsim {

// Distance from p to the segment a-b.
inline double point_segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 d = b - a;
  const double len2 = dot(d, d);
  const double t = len2 > 0 ? std::clamp(dot(p - a, d) / len2, 0.0, 1.0) : 0.0;
  return norm(p - (a + t * d));
}

// Whether segments a-b and c-d share a point (touching counts), by the signs of orientation tests.
inline bool segments_meet(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  auto side = [](Vec2 p, Vec2 q, Vec2 r) { return cross(q - p, r - p); };
  auto within = [](Vec2 p, Vec2 q, Vec2 r) {  // r, collinear with p-q, lies within its box
    return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= r.y &&
           r.y <= std::max(p.y, q.y);
  };
  const double d1 = side(c, d, a), d2 = side(c, d, b), d3 = side(a, b, c), d4 = side(a, b, d);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  return (d1 == 0 && within(c, d, a)) || (d2 == 0 && within(c, d, b)) || (d3 == 0 && within(a, b, c)) ||
         (d4 == 0 && within(a, b, d));
}

// Distance between segments a-b and c-d: zero when they meet, else the nearest of an end to the other.
inline double segment_distance(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  if (segments_meet(a, b, c, d)) return 0;
  return std::min({point_segment_distance(a, c, d), point_segment_distance(b, c, d), point_segment_distance(c, a, b),
                   point_segment_distance(d, a, b)});
}

// Squared distances, for tests against a squared radius that need no root: p to segment a-b, segment a-b
// to segment c-d, and p to triangle a, b, c (its inside counts; a flat triangle is its edges).
inline double point_segment_distance2(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 d = b - a, w = p - a;
  const double len2 = dot(d, d);
  const Vec2 e = w - (len2 > 0 ? std::clamp(dot(w, d) / len2, 0.0, 1.0) : 0.0) * d;
  return dot(e, e);
}

inline double segment_distance2(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  if (segments_meet(a, b, c, d)) return 0;
  return std::min({point_segment_distance2(a, c, d), point_segment_distance2(b, c, d), point_segment_distance2(c, a, b),
                   point_segment_distance2(d, a, b)});
}

inline double point_triangle_distance2(Vec2 p, Vec2 a, Vec2 b, Vec2 c) {
  const double area = cross(b - a, c - a), s1 = cross(b - a, p - a), s2 = cross(c - b, p - b), s3 = cross(a - c, p - c);
  if ((area > 0 && s1 >= 0 && s2 >= 0 && s3 >= 0) || (area < 0 && s1 <= 0 && s2 <= 0 && s3 <= 0)) return 0;
  return std::min(
      {point_segment_distance2(p, a, b), point_segment_distance2(p, b, c), point_segment_distance2(p, c, a)});
}

}  // namespace selfsim
