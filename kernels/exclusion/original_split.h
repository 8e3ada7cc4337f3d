// One split by the rule of Bowyer's own 2004 program (issue 21), written from a prose specification of it,
// operation for operation, so that his published lengths come out to every printed digit. Nothing here is
// his code. Splitting A→B with radius r:
//
// - Frame. M = (A + B)·0.5; (N0, c0) = line(A, B), N0 the unit normal to the left of A→B;
//   (N1, c1) = line(M, M + N0), so N1·x + c1 is the signed distance from the perpendicular bisector, positive
//   on A's side; h = 0.5·|B − A|; the point moves to P(t) = M + N0·t; ε = r·1e-8.
// - Limits. T⁺ starts at 1e100 and takes min(T⁺, candidate) then max(T⁺, 0) for each positive-side
//   candidate; T⁻ starts at −1e100 and takes max then min(T⁻, 0). So T⁺ = max(0, least candidate) and
//   T⁻ = min(0, greatest), whatever order the obstacles come in.
// - Segment test (an obstacle segment p→q): only if it meets the whole bisector line, endpoints included
//   (s in [0, 1], −0 too), and is not within ε of parallel to it; the candidate is where the bisector comes
//   within r of the obstacle's *infinite* line, T ∓ r/S before the crossing T (S the sine of the angle):
//   crossings at T ≥ 0 go to T⁺, at T < 0 to T⁻.
// - Vertex test (an obstacle point p, on the negative side iff N0·p + c0 < 0): for the end E (A or B) on
//   p's side of the bisector, if p is less than h + r from the bisector (strictly, and not on it), the
//   one or two lines through E tangent to p's disc of radius r cross the bisector at candidates for p's
//   side (accepted from −ε, or up to +ε, so that a crossing at M within rounding clamps that side). An E
//   inside the disc (D − r² < −ε²) or on p (D < ε²) imposes nothing.
// - Choice. t = T⁻ if |T⁻| > |T⁺|, else T⁺ (an exact tie goes to the left); P = M + N0·t, inserted even
//   when t = 0 (a stuck split: collinear halves).
//
// Every expression is evaluated in the order the specification gives (dot products first, then the
// constant), in plain double; the project builds without FMA contraction (no -march, ISO C++), which
// this relies on.
#pragma once

#include <algorithm>
#include <cmath>

#include "kernels/geom/vec2.h"

namespace selfsim::exclusion::original {

// His "BIG": a side that nothing stopped.
inline constexpr double unbounded = 1e100;

// A unit normal n and offset c with n·x + c the signed distance from the line u→v, positive on its left.
struct Line {
  Vec2 n;
  double c;
};

inline Line line(Vec2 u, Vec2 v) {
  const double dx = v.x - u.x, dy = v.y - u.y;
  const double length = std::sqrt(dx * dx + dy * dy);
  const Vec2 e{dx / length, dy / length};
  return {{-e.y, e.x}, (u.x * v.y - v.x * u.y) / length};
}

struct Frame {
  Vec2 a, b, m, n0, n1;
  double c0, c1, h, r, eps;

  Frame(Vec2 from, Vec2 to, double radius) : a(from), b(to), r(radius) {
    m = {(a.x + b.x) * 0.5, (a.y + b.y) * 0.5};
    const Line ab = line(a, b);
    n0 = ab.n;
    c0 = ab.c;
    const Line bisector = line(m, {m.x + n0.x, m.y + n0.y});
    n1 = bisector.n;
    c1 = bisector.c;
    const double dx = b.x - a.x, dy = b.y - a.y;
    h = 0.5 * std::sqrt(dx * dx + dy * dy);
    eps = r * 1e-8;
  }
  Vec2 at(double t) const { return {m.x + n0.x * t, m.y + n0.y * t}; }
};

struct Limits {
  double positive = unbounded, negative = -unbounded;

  // NaN candidates are ignored (std::min and std::max keep their first argument).
  void offer_positive(double t) {
    positive = std::min(positive, t);
    positive = std::max(positive, 0.0);
  }
  void offer_negative(double t) {
    negative = std::max(negative, t);
    negative = std::min(negative, 0.0);
  }
  // The chosen move: the negative side only when it reaches strictly farther.
  double chosen() const { return std::abs(negative) > std::abs(positive) ? negative : positive; }
};

inline double dot2(Vec2 u, Vec2 v) { return u.x * v.x + u.y * v.y; }

// The obstacle segment p→q.
inline void segment_test(const Frame& f, Vec2 p, Vec2 q, Limits& l) {
  const Vec2 d{q.x - p.x, q.y - p.y};
  const double den = dot2(d, f.n1);
  if (std::abs(den) < f.eps) return;
  const double s = -(f.c1 + dot2(f.n1, p)) / den;
  if (s < 0 || s > 1) return;
  const Line o = line(p, q);
  const double den2 = dot2(o.n, f.n0);
  if (std::abs(den2) < f.eps) return;
  const double t = -(o.c + dot2(o.n, f.m)) / den2;
  const double length = std::sqrt(d.x * d.x + d.y * d.y);
  const Vec2 u{d.x / length, d.y / length};
  const double kappa = dot2(u, f.n0);
  const double k = 1 / std::sqrt(1 - kappa * kappa);
  if (t < 0)
    l.offer_negative(t + f.r * k);
  else
    l.offer_positive(t - f.r * k);
}

// Where the line through e with unit normal g crosses the bisector, as a candidate for p's side.
inline void tangent_crossing(const Frame& f, Vec2 g, Vec2 e, bool negative, Limits& l) {
  const double gamma = -dot2(g, e);
  const double den = dot2(g, f.n0);
  if (!(std::abs(den) > f.eps)) return;
  const double t = -(gamma + dot2(g, f.m)) / den;
  if (negative) {
    if (t < f.eps) l.offer_negative(t);
  } else if (t > -f.eps) {
    l.offer_positive(t);
  }
}

// The obstacle point p.
inline void vertex_test(const Frame& f, Vec2 p, Limits& l) {
  const double g = dot2(f.n1, p) + f.c1;
  const double band = f.h + f.r;
  Vec2 e;
  if (g > 0 && g < band)
    e = f.a;
  else if (-g > 0 && -g < band)
    e = f.b;
  else
    return;
  const bool negative = dot2(f.n0, p) + f.c0 < 0;
  const Vec2 k{p.x - e.x, p.y - e.y};
  const double d = k.x * k.x + k.y * k.y, rr = f.r * f.r, ee = f.eps * f.eps;
  const double rest = d - rr;
  if (d < ee || rest < -ee) return;
  if (rest < ee) {
    // E on the circle: one tangent (his program measures it twice; once gives the same min and max).
    const double i = 1 / d;
    tangent_crossing(f, {(-k.x * f.r) * i, (-k.y * f.r) * i}, e, negative, l);
    return;
  }
  const double rho = std::sqrt(rest), i = 1 / d;
  tangent_crossing(f, {i * (-k.y * rho - f.r * k.x), i * (k.x * rho - f.r * k.y)}, e, negative, l);
  tangent_crossing(f, {i * (-k.y * rho + f.r * k.x), i * (k.x * rho + f.r * k.y)}, e, negative, l);
}

}  // namespace selfsim::exclusion::original
