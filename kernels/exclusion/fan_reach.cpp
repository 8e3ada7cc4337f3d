#include "kernels/exclusion/fan_reach.h"

#include <algorithm>
#include <cmath>

#include "kernels/base/error.h"
#include "kernels/geom/distance3.h"
#include "kernels/geom/segment2.h"

namespace selfsim::exclusion {

namespace {

// {t : c0 + c1·t + c2·t² > 0}.
IntervalSet positive_quadratic(double c0, double c1, double c2) { return negative_quadratic(-c2, -c1 / 2, -c0); }

Interval hull(Interval a, Interval b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)};
}

// The pieces of the terms for a point p(t) = t·d (coordinates taken from m, d a unit vector): each is the set
// of t where the piece comes within rho, as quadratics a·t² + 2b·t + c < 0 and their intersections. A
// term's set is the hull of its pieces' sets: the pieces cover it, and it is one interval.
struct Line {
  Vec3 d;

  // p(t) within rho of point w: |t·d - w|² < rho².
  Interval point(Vec3 w, double rho) const { return negative_quadratic(1, -dot(d, w), dot(w, w) - rho * rho).hull(); }

  // p(t) within rho of segment u-v's inside, its foot strictly between u and v.
  Interval segment_inside(Vec3 u, Vec3 v, double rho) const {
    const Vec3 e = v - u, a = cross(d, e), b = cross(u, e);  // cross(t·d - u, e) = t·a - b
    const double ee = dot(e, e), de = dot(d, e), ue = dot(u, e);
    if (!(ee > 0)) return {};
    const IntervalSet near = negative_quadratic(dot(a, a), -dot(a, b), dot(b, b) - rho * rho * ee);
    const IntervalSet along = intersect(positive_linear(-ue, de), positive_linear(ee + ue, -de));  // 0 < foot < ee
    return intersect(near, along).hull();
  }

  Interval segment(Vec3 u, Vec3 v, double rho) const {
    return hull(hull(point(u, rho), point(v, rho)), segment_inside(u, v, rho));
  }

  // p(t) within rho of triangle a, b, c: its edges, or its inside (a flat triangle has none).
  Interval triangle(Vec3 a, Vec3 b, Vec3 c, double rho) const {
    const Interval edges = hull(hull(segment(a, b, rho), segment(b, c, rho)), segment(c, a, rho));
    const Vec3 n = cross(b - a, c - a);
    const double nn = dot(n, n), longest = std::max({dot(b - a, b - a), dot(c - b, c - b), dot(a - c, a - c)});
    if (!(nn > 1e-24 * longest * longest)) return edges;
    // Within rho of the plane, |dot(t·d - a, n)| < rho·|n|, and the foot inside each edge u-v:
    // dot(cross(v - u, t·d - u), n) > 0.
    const double dn = dot(d, n), an = dot(a, n), band = rho * std::sqrt(nn);
    IntervalSet s = intersect(positive_linear(band + an, -dn), positive_linear(band - an, dn));
    for (const auto& [u, v] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}})
      s = intersect(s, positive_linear(-dot(cross(v - u, u), n), dot(cross(v - u, d), n)));
    return hull(edges, s.hull());
  }

  // w within rho of the segment from static end x to p(t) but not of p(t) itself (point() adds that): the
  // rest of the shadow of w's ball seen from x.
  Interval shadow(Vec3 x, Vec3 w, double rho) const {
    const Vec3 wx = w - x, P = cross(d, wx), Q = cross(x, wx);  // cross(t·d - x, wx) = t·P - Q
    const double r2 = rho * rho, wd = dot(wx, d), wxx = dot(wx, x);
    // The line through x and p(t) passes within rho of w: |t·P - Q|² < rho²·|t·d - x|².
    const IntervalSet line =
        negative_quadratic(dot(P, P) - r2, -(dot(P, Q) - r2 * dot(d, x)), dot(Q, Q) - r2 * dot(x, x));
    // w's foot strictly between x and p(t): 0 < dot(wx, t·d - x) < |t·d - x|².
    const IntervalSet foot_after_x = positive_linear(-wxx, wd);
    const IntervalSet foot_before_p = positive_quadratic(dot(x, x) + wxx, -(2 * dot(d, x) + wd), 1);
    return intersect_hull(intersect(line, foot_after_x), foot_before_p);
  }

  // w within rho of the inside of triangle x, y, p(t), its foot strictly inside.
  Interval face(Vec3 x, Vec3 y, Vec3 w, double rho) const {
    const Vec3 yx = y - x, wx = w - x, wy = w - y;
    const Vec3 n0 = -cross(yx, x), n1 = cross(yx, d);  // the normal cross(yx, t·d - x) = n0 + t·n1
    const double r2 = rho * rho, w0 = dot(wx, n0), w1 = dot(wx, n1);
    // Within rho of the plane: (w0 + t·w1)² < rho²·|n0 + t·n1|².
    const IntervalSet plane =
        negative_quadratic(w1 * w1 - r2 * dot(n1, n1), w0 * w1 - r2 * dot(n0, n1), w0 * w0 - r2 * dot(n0, n0));
    // The foot inside each edge, x-y, y-p, p-x: dot(cross(edge, w - edge start), n) > 0.
    const Vec3 c = cross(yx, wx);
    const IntervalSet inside_xy = positive_linear(dot(c, n0), dot(c, n1));
    const Vec3 k0 = -cross(y, wy), k1 = cross(d, wy);  // cross(t·d - y, wy)
    const IntervalSet inside_yp = positive_quadratic(dot(k0, n0), dot(k0, n1) + dot(k1, n0), dot(k1, n1));
    const Vec3 j0 = cross(x, wx), j1 = -cross(d, wx);  // cross(x - t·d, w - p) = cross(x - t·d, wx)
    const IntervalSet inside_px = positive_quadratic(dot(j0, n0), dot(j0, n1) + dot(j1, n0), dot(j1, n1));
    return intersect_hull(intersect(intersect(plane, inside_xy), inside_yp),
                          intersect(inside_px, not_parallel(n0, n1, yx, x)),
                          [&](Interval part) { return point_triangle_distance(w, x, y, inner_point(part) * d) < rho; });
  }

  // The face and the inside of two segments are products of near-cancelling terms where the point is in
  // or near the plane of what it meets (a flat surface's boundary moving in its plane): rounding can leave
  // slivers there that no distance confirms. Each part of their sets is checked by the distance at a point
  // of it.
  //
  // Where t·d - x is not within 1e-10 radians of parallel to e: |cross(e, t·d - x)|² = |n0 + t·n1|² above
  // 1e-20·|e|²·|t·d - x|². Near parallel the face and the inside of two segments are ill-conditioned (every
  // sign test is a product of rounding), and the nearest points are on their edges or ends instead, which
  // other pieces measure.
  IntervalSet not_parallel(Vec3 n0, Vec3 n1, Vec3 e, Vec3 x) const {
    const double k = 1e-20 * dot(e, e);
    return positive_quadratic(dot(n0, n0) - k * dot(x, x), 2 * (dot(n0, n1) + k * dot(d, x)), dot(n1, n1) - k);
  }

  // Segment u-v within rho of the spoke from z to p(t), the nearest points inside both.
  Interval spoke_inside(Vec3 z, Vec3 u, Vec3 v, double rho) const {
    const Vec3 e = v - u, uz = u - z;
    const Vec3 n0 = -cross(z, e), n1 = cross(d, e);  // cross(t·d - z, e) = n0 + t·n1
    const double r2 = rho * rho, w0 = dot(uz, n0), w1 = dot(uz, n1);
    const double nn0 = dot(n0, n0), nn1 = 2 * dot(n0, n1), nn2 = dot(n1, n1);  // |n|² = nn0 + nn1·t + nn2·t²
    const IntervalSet near = negative_quadratic(w1 * w1 - r2 * nn2, w0 * w1 - r2 * nn1 / 2, w0 * w0 - r2 * nn0);
    // The spoke's parameter dot(cross(uz, e), n) / |n|² in (0, 1).
    const Vec3 c = cross(uz, e);
    const double c0 = dot(c, n0), c1 = dot(c, n1);
    const IntervalSet spoke_param = intersect(positive_linear(c0, c1), positive_quadratic(nn0 - c0, nn1 - c1, nn2));
    // The segment's parameter dot(cross(uz, t·d - z), n) / |n|² in (0, 1).
    const Vec3 g0 = -cross(uz, z), g1 = cross(uz, d);
    const double q0 = dot(g0, n0), q1 = dot(g0, n1) + dot(g1, n0), q2 = dot(g1, n1);
    const IntervalSet segment_param =
        intersect(positive_quadratic(q0, q1, q2), positive_quadratic(nn0 - q0, nn1 - q1, nn2 - q2));
    return intersect_hull(
        intersect(near, spoke_param), intersect(segment_param, not_parallel(n0, n1, e, z)),
        [&](Interval part) { return segment_segment_distance(u, v, z, inner_point(part) * d) < rho; });
  }
};

bool shared(std::uint32_t a, std::uint32_t b) { return a != no_vertex && a == b; }

// term() for a term that is never below sqrt(least2) wherever the point goes on its line: with its radius at
// most that, its set is empty, and neither its distance where it starts (d0()) nor its set is needed.
// A neighbour's term (close > 0) that starts below r (its distance where it starts is at most
// sqrt(upper2), a cheap bound) keeps only `close`: when it never comes that near either, its distance is not
// needed. Most terms of a deep level's move are such.
template <class D0, class SetFor>
void bounded_term(Reach& reach, double r, double close, double least2, double upper2, D0 d0, SetFor set_for) {
  if (least2 >= r * r) return;
  if (close > 0 && least2 >= close * close && upper2 < r * r) return;
  const double start = d0(), rho = term_radius(r, start, close);
  if (rho > 0 && least2 >= rho * rho) return;
  term(reach, r, start, either, 0, set_for, close);
}

}  // namespace

FanView::FanView(const FanMove& f) : move(f) {
  const Vec3 d = f.d;
  const Vec3 a = std::abs(d.x) <= std::abs(d.y) && std::abs(d.x) <= std::abs(d.z) ? Vec3{1, 0, 0}
                 : std::abs(d.y) <= std::abs(d.z)                                 ? Vec3{0, 1, 0}
                                                                                  : Vec3{0, 0, 1};
  e1 = normalized(cross(d, a));
  e2 = cross(d, e1);
  if (f.ring.size() > max_ring)
    throw Error("a fan of more than 6 ring points (a fault in selfsim: please report the recipe)");
  for (std::size_t i = 0; i < f.ring.size(); ++i) {
    ring[i] = f.ring[i] - f.m;
    flat[i] = flat_of(ring[i]), along[i] = along_of(ring[i]);
    box.add(flat[i], along[i]);
  }
}

void limit_fan(const FanView& fan, const Obstacle& o, double r, Reach& reach, const TermsWanted& wanted,
               const std::array<VertexPieces*, 3>& pieces) {
  const FanMove& f = fan.move;
  const Line line{f.d};
  const std::size_t n = f.ring.size(), triangles = f.closed ? n : n - 1;
  auto ring = [&](std::size_t i) { return fan.ring[i % n]; };
  std::array<Vec3, 3> at{};
  for (int k = 0; k < o.corners; ++k) at[k] = o.at[k] - f.m;
  const Vec3 origin{};
  // The fan and the obstacle in the frame square to the line. A term acts only where its fan piece comes
  // within r of its obstacle piece. While the point stays within the reach left on each side, the piece
  // stays in the box of its static points and the point's two farthest places: where the obstacle piece's
  // box is r or more from that one, the term needs no distance. Nor does the whole obstacle, likewise.
  FrameBox fan_box = fan.box, obstacle_box;
  fan_box.add({}, reach.positive);
  fan_box.add({}, -reach.negative);
  std::array<Vec2, 3> at_flat;
  std::array<double, 3> at_along;
  for (int k = 0; k < o.corners; ++k) {
    at_flat[k] = fan.flat_of(at[k]), at_along[k] = fan.along_of(at[k]);
    obstacle_box.add(at_flat[k], at_along[k]);
  }
  if (fan_box.gap2(obstacle_box) >= r * r) return;
  auto out_of_reach = [&](std::initializer_list<std::size_t> fan_static, std::initializer_list<int> piece) {
    FrameBox a, b;
    a.add({}, reach.positive);
    a.add({}, -reach.negative);
    for (std::size_t i : fan_static) a.add(fan.flat[i % n], fan.along[i % n]);
    for (int k : piece) b.add(at_flat[k], at_along[k]);
    return a.gap2(b) >= r * r;
  };
  // The pieces that several terms share, solved once at the full radius: where p comes near obstacle
  // corner k, and where corner k comes near the spoke from ring point j (kept across the move's obstacles
  // in the caller's pieces), and where p comes near the inside of obstacle edge k (across the spokes).
  auto point_piece = [&](int k, double rho) {
    VertexPieces* kept = pieces[k];
    if (!kept || rho != r) return line.point(at[k], rho);
    if (!(kept->known & VertexPieces::point_known)) {
      kept->point = line.point(at[k], r);
      kept->known |= VertexPieces::point_known;
    }
    return kept->point;
  };
  auto shadow_piece = [&](std::size_t j, int k, double rho) {
    j %= n;
    VertexPieces* kept = pieces[k];
    if (!kept || rho != r) return line.shadow(ring(j), at[k], rho);
    if (!(kept->known & 1u << j)) {
      kept->shadow[j] = line.shadow(ring(j), at[k], r);
      kept->known |= 1u << j;
    }
    return kept->shadow[j];
  };
  std::array<Interval, 3> edge_inside;
  std::array<bool, 3> edge_inside_known{};
  auto edge_inside_piece = [&](int k, double rho) {
    const Vec3 u = at[k], v = at[(k + 1) % o.corners];
    if (rho != r) return line.segment_inside(u, v, rho);
    if (!edge_inside_known[k]) edge_inside[k] = line.segment_inside(u, v, r), edge_inside_known[k] = true;
    return edge_inside[k];
  };
  // The least a term can be anywhere on the line: the distance between its pieces seen along the line,
  // where every place of a fan piece, its static points and p(t), lands in the flat piece of the static
  // points and m. Most terms near a deep level's move never come below their radius at all: this finds them
  // without solving.
  const Vec2 m_flat{};
  const bool all_near = o.near[0] && (o.corners < 2 || o.near[1]) && (o.corners < 3 || o.near[2]);
  const double whole_close = all_near ? o.close : 0;
  if (o.corners == 1)
    bounded_term(
        reach, r, whole_close, dot(at_flat[0], at_flat[0]), dot(at[0], at[0]), [&] { return norm(at[0]); },
        [&](double rho) { return line.point(at[0], rho); });
  else if (o.corners == 2)
    bounded_term(
        reach, r, whole_close, point_segment_distance2(m_flat, at_flat[0], at_flat[1]),
        std::min(dot(at[0], at[0]), dot(at[1], at[1])), [&] { return point_segment_distance(origin, at[0], at[1]); },
        [&](double rho) { return line.segment(at[0], at[1], rho); });
  else
    bounded_term(
        reach, r, whole_close, point_triangle_distance2(m_flat, at_flat[0], at_flat[1], at_flat[2]),
        std::min({dot(at[0], at[0]), dot(at[1], at[1]), dot(at[2], at[2])}),
        [&] { return point_triangle_distance(origin, at[0], at[1], at[2]); },
        [&](double rho) { return line.triangle(at[0], at[1], at[2], rho); });
  // Corner terms: corner k within rho of fan triangle x, y, p(t) (x and y are static, never within rho).
  for (int k = 0; k < o.corners; ++k) {
    if (!wanted.corner[k]) continue;
    for (std::size_t i = 0; i < triangles; ++i) {
      if (shared(o.id[k], f.ring_id[i]) || shared(o.id[k], f.ring_id[(i + 1) % n])) continue;
      const Vec3 x = ring(i), y = ring(i + 1), w = at[k];
      if (out_of_reach({i, i + 1}, {k})) continue;
      const double least = point_triangle_distance2(at_flat[k], fan.flat[i], fan.flat[(i + 1) % n], m_flat);
      const double upper = o.near[k] ? std::min({dot(w - x, w - x), dot(w - y, w - y), dot(w, w)}) : 0;
      bounded_term(
          reach, r, o.near[k] ? o.close : 0, least, upper, [&] { return point_triangle_distance(w, x, y, origin); },
          [&](double rho) {
            return hull(hull(line.face(x, y, w, rho), point_piece(k, rho)),
                        hull(shadow_piece(i, k, rho), shadow_piece(i + 1, k, rho)));
          });
    }
  }
  // Edge terms: obstacle edge k, u-v, within rho of the spoke from z to p(t) (z is static, never within rho).
  const int edges = o.corners == 3 ? 3 : o.corners - 1;
  for (int k = 0; k < edges; ++k) {
    if (!wanted.edge[k]) continue;
    const int k1 = (k + 1) % o.corners;
    for (std::size_t j = 0; j < n; ++j) {
      if (shared(o.id[k], f.ring_id[j]) || shared(o.id[k1], f.ring_id[j])) continue;
      const Vec3 z = ring(j), u = at[k], v = at[k1];
      if (out_of_reach({j}, {k, k1})) continue;
      const double least = segment_distance2(at_flat[k], at_flat[k1], fan.flat[j], m_flat);
      const double upper =
          o.near[k] && o.near[k1] ? std::min({dot(u - z, u - z), dot(u, u), dot(v - z, v - z), dot(v, v)}) : 0;
      bounded_term(
          reach, r, o.near[k] && o.near[k1] ? o.close : 0, least, upper,
          [&] { return segment_segment_distance(u, v, z, origin); },
          [&](double rho) {
            const Interval ends = hull(hull(point_piece(k, rho), point_piece(k1, rho)),
                                       hull(shadow_piece(j, k, rho), shadow_piece(j, k1, rho)));
            return hull(ends, hull(edge_inside_piece(k, rho), line.spoke_inside(z, u, v, rho)));
          });
    }
  }
}

}  // namespace selfsim::exclusion
