#include "kernels/geom/triangle_contact.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "kernels/geom/distance3.h"

namespace selfsim {

namespace {

// ---- Apart: the closest points of two triangles are an edge of one crossing the other, a corner of one
// nearest the other, or two edges nearest each other in their interiors; a test of each is the whole
// distance, coplanar and degenerate cases included. Separating axes first reject, cheaply, nearly every pair
// that is apart.

// True when a and b's projections on `axis` are more than eps (times the axis's length) apart: then the
// triangles are too. Only a shortcut: a zero axis separates nothing. Projected from a's first corner, so
// that rounding scales with the triangles' size, not with their distance from the origin.
bool apart_on(Vec3 axis, const ContactTriangle& a, const ContactTriangle& b, double eps) {
  const Vec3 o = a.v[0];
  const double a0 = 0, a1 = dot(a.v[1] - o, axis), a2 = dot(a.v[2] - o, axis);
  const double b0 = dot(b.v[0] - o, axis), b1 = dot(b.v[1] - o, axis), b2 = dot(b.v[2] - o, axis);
  const double gap =
      std::max(std::min({b0, b1, b2}) - std::max({a0, a1, a2}), std::min({a0, a1, a2}) - std::max({b0, b1, b2}));
  return gap > 0 && gap * gap > eps * eps * dot(axis, axis);
}

// Separating axes, cheapest and likeliest first: the normals (which settle most pairs of a curved surface),
// each triangle's edges' outward directions in its own plane (coplanar pairs), and the edges' cross
// products. Together they find a gap wider than eps between any pair they do not let through.
bool separated(const ContactTriangle& a, const ContactTriangle& b, double eps) {
  if ((!a.flat && apart_on(a.n, a, b, eps)) || (!b.flat && apart_on(b.n, a, b, eps))) return true;
  for (int k = 0; k < 3; ++k) {
    if (!a.flat && apart_on(cross(a.v[(k + 1) % 3] - a.v[k], a.n), a, b, eps)) return true;
    if (!b.flat && apart_on(cross(b.v[(k + 1) % 3] - b.v[k], b.n), a, b, eps)) return true;
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (apart_on(cross(a.v[(i + 1) % 3] - a.v[i], b.v[(j + 1) % 3] - b.v[j]), a, b, eps)) return true;
  return false;
}

// Where the segment p-q passes through t's plane strictly between its ends, if that point is in t. (An end on
// the plane is a corner near t; a crossing just outside t is near one of t's edges.)
std::optional<Vec3> crossing(Vec3 p, Vec3 q, const ContactTriangle& t) {
  if (t.flat) return std::nullopt;
  const double dp = dot(p - t.v[0], t.n), dq = dot(q - t.v[0], t.n);
  if (!((dp < 0 && dq > 0) || (dp > 0 && dq < 0))) return std::nullopt;
  const Vec3 x = p + (dp / (dp - dq)) * (q - p);
  if (t.contains(x)) return x;
  return std::nullopt;
}

// The midpoint of the closest points of segments p1-q1 and p2-q2 when those lie inside both segments and
// within eps of each other. Lines within 1e-12 radians of parallel are left to the corner tests: their
// closest points then include an end to rounding. The line parameters come from cross products, which keep
// their precision for nearly parallel edges where the normal equations would cancel.
std::optional<Vec3> edges_meet(Vec3 p1, Vec3 q1, Vec3 p2, Vec3 q2, double eps2) {
  const Vec3 d1 = q1 - p1, d2 = q2 - p2, n = cross(d1, d2);
  const double nn = dot(n, n);
  if (!(nn > 1e-24 * dot(d1, d1) * dot(d2, d2))) return std::nullopt;
  const Vec3 w = p2 - p1;
  const double s = dot(cross(w, d2), n) / nn, t = dot(cross(w, d1), n) / nn;
  if (!(s >= 0 && s <= 1 && t >= 0 && t <= 1)) return std::nullopt;
  const Vec3 x1 = p1 + s * d1, x2 = p2 + t * d2;
  if (dot(x1 - x2, x1 - x2) > eps2) return std::nullopt;
  return 0.5 * (x1 + x2);
}

// A point where a and b meet (are within eps of each other), if they do.
std::optional<Vec3> contact(const ContactTriangle& a, const ContactTriangle& b, double eps) {
  if (separated(a, b, eps)) return std::nullopt;
  for (int k = 0; k < 3; ++k) {
    if (auto x = crossing(a.v[k], a.v[(k + 1) % 3], b)) return x;
    if (auto x = crossing(b.v[k], b.v[(k + 1) % 3], a)) return x;
  }
  const double eps2 = eps * eps;
  for (int k = 0; k < 3; ++k) {
    const Vec3 qa = closest_on_triangle(a.v[k], b.v[0], b.v[1], b.v[2]);
    if (dot(qa - a.v[k], qa - a.v[k]) <= eps2) return 0.5 * (qa + a.v[k]);
    const Vec3 qb = closest_on_triangle(b.v[k], a.v[0], a.v[1], a.v[2]);
    if (dot(qb - b.v[k], qb - b.v[k]) <= eps2) return 0.5 * (qb + b.v[k]);
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (auto x = edges_meet(a.v[i], a.v[(i + 1) % 3], b.v[j], b.v[(j + 1) % 3], eps2)) return x;
  return std::nullopt;
}

// ---- Neighbours: triangles that share corners meet there by construction; they meet wrongly when they
// also meet elsewhere: two triangles of a fan that cross, or fold onto each other.

// A triangle seen from one of its corners v: its other corners x, y in order, and its normal n (the same
// from any corner). Tolerances below compare squares: no square roots in the inner loop.
struct Wedge {
  Vec3 v, x, y, n;
  Wedge(const ContactTriangle& t, int k) : v(t.v[k]), x(t.v[(k + 1) % 3]), y(t.v[(k + 2) % 3]), n(t.n) {}

  // s > tol·r for r² given: s positive and beyond the tolerance, without the root.
  static bool above(double s, double tol2_r2) { return s > 0 && s * s > tol2_r2; }
  // Whether direction d points into the wedge at v, strictly (beyond 1e-12 radians of its sides).
  bool contains(Vec3 d) const {
    const Vec3 ex = x - v, ey = y - v;
    const double dn = 1e-24 * dot(d, d) * dot(n, n);
    return above(dot(cross(ex, d), n), dn * dot(ex, ex)) && above(dot(cross(d, ey), n), dn * dot(ey, ey));
  }
  // Whether the other wedge's corners lie clearly on one side of this one's plane (beyond 1e-9 of their
  // distance from v): then the two meet only at v.
  bool beside(const Wedge& o) const {
    const double s1 = dot(o.x - v, n), s2 = dot(o.y - v, n);
    const double tol = 1e-18 * dot(n, n) * std::max(dot(o.x - v, o.x - v), dot(o.y - v, o.y - v));
    return (above(s1, tol) && above(s2, tol)) || (above(-s1, tol) && above(-s2, tol));
  }
};

// Triangles sharing exactly one corner v meet elsewhere when some ray from v lies in both: the line their
// planes share, if it points into both wedges, or, for coplanar triangles, one's side pointing into the
// other's wedge.
bool share_more_than_a_corner(const Wedge& a, const Wedge& b) {
  if (a.beside(b) || b.beside(a)) return false;  // most pairs of a smooth surface
  const Vec3 d = cross(a.n, b.n);
  if (dot(d, d) > 1e-18 * dot(a.n, a.n) * dot(b.n, b.n)) {  // the planes cross at more than 1e-9 radians
    for (const Vec3 dir : {d, -1.0 * d})
      if (a.contains(dir) && b.contains(dir)) return true;
    return false;
  }
  return a.contains(b.x - b.v) || a.contains(b.y - b.v) || b.contains(a.x - a.v) || b.contains(a.y - a.v);
}

// Corners a triangle shares with another, by point index: 0 to 3.
int shared_corners(const Triangle& a, const Triangle& b) {
  int n = 0;
  for (std::uint32_t p : a) n += int(p == b[0] || p == b[1] || p == b[2]);
  return n;
}

// Where two neighbours (sharing one or two corners) meet other than along what they share, if they do: one
// corner shared, a crossing or overlap beyond it; an edge shared, a fold (the two third corners on the same
// side of the edge, within eps of one plane).
std::optional<Vec3> neighbours_meet(const Triangle& ia, const Triangle& ib, const ContactTriangle& a,
                                    const ContactTriangle& b, double eps) {
  if (a.flat || b.flat) return std::nullopt;
  const int shared = shared_corners(ia, ib);
  if (shared == 1) {
    int ka = 0, kb = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (ia[i] == ib[j]) ka = i, kb = j;
    if (!share_more_than_a_corner(Wedge(a, ka), Wedge(b, kb))) return std::nullopt;
    return a.v[ka];
  }
  if (shared == 2) {
    int third_a = 0, third_b = 0;
    for (int i = 0; i < 3; ++i) {
      if (ia[i] != ib[0] && ia[i] != ib[1] && ia[i] != ib[2]) third_a = i;
      if (ib[i] != ia[0] && ib[i] != ia[1] && ib[i] != ia[2]) third_b = i;
    }
    const Vec3 u = a.v[(third_a + 1) % 3], w = a.v[(third_a + 2) % 3], pa = a.v[third_a], pb = b.v[third_b];
    const bool same_side = dot(cross(w - u, pa - u), cross(w - u, pb - u)) > 0;
    if (same_side && std::abs(dot(pb - u, a.n)) <= eps * norm(a.n)) return pb;
  }
  return std::nullopt;
}

}  // namespace

std::optional<Vec3> triangles_meet(const Triangle& ia, const Triangle& ib, const ContactTriangle& a,
                                   const ContactTriangle& b, double eps) {
  return shared_corners(ia, ib) > 0 ? neighbours_meet(ia, ib, a, b, eps) : contact(a, b, eps);
}

}  // namespace selfsim
