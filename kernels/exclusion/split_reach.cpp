#include "kernels/exclusion/split_reach.h"

#include <algorithm>
#include <cmath>

namespace selfsim::exclusion {

namespace {

// The split's frame: coordinates (s along e, t along n) from m. The point moves along the t axis; a is at
// (-h, 0) and b at (h, 0).
struct Local {
  double s, t;
};

Local local(const SplitFrame& f, Vec2 q) { return {dot(q - f.m, f.e), dot(q - f.m, f.n)}; }

// {t : (0, t) within rho of point w}.
Interval disc_set(Local w, double rho) {
  const double k = rho * rho - w.s * w.s;
  if (!(k > 0)) return {};
  const double half = std::sqrt(k);
  return {w.t - half, w.t + half};
}

// {t : (0, t) within rho of segment u-v}: the axis meets the capsule around u-v, one interval.
Interval capsule_set(Local u, Local v, double rho) {
  IntervalSet s;
  s.add(disc_set(u, rho));
  s.add(disc_set(v, rho));
  const double ds = v.s - u.s, dt = v.t - u.t, len = std::sqrt(ds * ds + dt * dt);
  if (len > 0) {
    // Across the segment's line: (ds·(t - ut) + dt·us) / len; along it: (dt·(t - ut) - ds·us) / len.
    const double c0 = (dt * u.s - ds * u.t) / len, c1 = ds / len, g0 = (-ds * u.s - dt * u.t) / len, g1 = dt / len;
    const IntervalSet strip = intersect(intersect(positive_linear(rho - c0, -c1), positive_linear(rho + c0, c1)),
                                        intersect(positive_linear(g0, g1), positive_linear(len - g0, -g1)));
    s.add(strip.hull());
  }
  return s.hull();
}

// {t : w within rho of the segment from an end to (0, t)}, the end at distance h behind the axis and w at
// `sigma` in front of that end (sigma = h + ws from a, h - ws from b), wt along n. The axis meets the convex
// set of points q whose segment from the end reaches the disc around w: one interval.
Interval shadow_set(double h, double sigma, Local w, double rho) {
  // The line from the end through (0, t) passes within rho of w, w's foot lying between the two.
  const IntervalSet line =
      negative_quadratic(sigma * sigma - rho * rho, -h * w.t * sigma, h * h * (w.t * w.t - rho * rho));
  const IntervalSet foot =
      intersect(positive_linear(h * sigma, w.t), negative_quadratic(-1, w.t / 2, h * sigma - h * h));
  IntervalSet s;
  s.add(intersect(line, foot).hull());
  s.add(disc_set(w, rho));  // or (0, t) itself within rho of w
  return s.hull();
}

// Distance from w to the segment from an end to m, in the frame: the end at sigma = 0, m at sigma = h.
double start_distance(double h, double sigma, Local w) {
  const double along = std::clamp(sigma, 0.0, h) - sigma;
  return std::sqrt(along * along + w.t * w.t);
}

// The point of segment u-v nearest m (the origin).
Local nearest_to_origin(Local u, Local v) {
  const double ds = v.s - u.s, dt = v.t - u.t, len2 = ds * ds + dt * dt;
  const double k = len2 > 0 ? std::clamp(-(u.s * ds + u.t * dt) / len2, 0.0, 1.0) : 0.0;
  return {u.s + k * ds, u.t + k * dt};
}

// Whether w, at sigma in front of an end and w.t along n, is farther than r from every segment from that
// end to (0, t) with t in [-negative, positive]: beyond one of the two slanted sides of their triangle.
bool outside_fan(double h, double sigma, Local w, double positive, double negative, double r) {
  if (std::isinf(positive) || std::isinf(negative)) return false;
  const double above = h * w.t - positive * sigma, below = -h * w.t - negative * sigma;
  return (above > 0 && above * above > r * r * (positive * positive + h * h)) ||
         (below > 0 && below * below > r * r * (negative * negative + h * h));
}

}  // namespace

SplitFrame::SplitFrame(Vec2 from, Vec2 to) : a(from), b(to), m(0.5 * (from + to)) {
  const double len = norm(to - from);
  e = (1 / len) * (to - from);
  n = {-e.y, e.x};
  h = 0.5 * len;
}

void limit_exact(const SplitFrame& f, Vec2 u, Vec2 v, double r, Reach& reach, bool u_terms, bool v_terms) {
  const Local U = local(f, u), V = local(f, v);
  // Beyond the moves still allowed by more than r, a point is too far to matter (the shortcut only skips
  // work: an empty set changes nothing).
  auto beyond = [&](Local w) { return w.t > reach.positive + r || w.t < -reach.negative - r; };
  const bool both_above = U.t > reach.positive + r && V.t > reach.positive + r;
  const bool both_below = U.t < -reach.negative - r && V.t < -reach.negative - r;
  if (!both_above && !both_below) {
    // The point's distance to u-v is convex in t with slope -c.t / d0 at t = 0, c the nearest point: it
    // shrinks only towards c.
    const Local c = nearest_to_origin(U, V);
    term(reach, r, std::sqrt(c.s * c.s + c.t * c.t), side_of(c.t), 0,
         [&](double rho) { return capsule_set(U, V, rho); });
  }
  for (int k = 0; k < (u == v ? 1 : 2); ++k) {
    const Vec2 w = k == 0 ? u : v;
    const Local W = k == 0 ? U : V;
    if (!(k == 0 ? u_terms : v_terms) || w == f.a || w == f.b || beyond(W)) continue;
    for (const double sigma : {f.h + W.s, f.h - W.s}) {
      // Farther than r from every segment from that end (behind it, past the axis, or beside the fan).
      if (sigma < -r || sigma > f.h + r || outside_fan(f.h, sigma, W, reach.positive, reach.negative, r)) continue;
      // Turning the new segment away from w (t of the other sign than w's) keeps every point of it at least
      // as far from w as the old one's; and while w lies behind the end (sigma < 0) the end stays nearest
      // until t·w.t reaches h·|sigma|.
      const double after = sigma < 0 ? f.h * -sigma / std::abs(W.t) : 0;
      term(reach, r, start_distance(f.h, sigma, W), side_of(W.t), after,
           [&](double rho) { return shadow_set(f.h, sigma, W, rho); });
    }
  }
}

void limit_vertex(const SplitFrame& f, Vec2 u, Vec2 v, double r, Reach& reach) {
  // (a) Crossing the bisector line (through m along n): the point stops where it comes within r of the
  // obstacle, and never passes it, however near m it crosses.
  const double su = dot(u - f.m, f.e), sv = dot(v - f.m, f.e);
  if ((su <= 0 && sv >= 0) || (su >= 0 && sv <= 0)) {
    const double tu = dot(u - f.m, f.n), tv = dot(v - f.m, f.n);
    const double tc = su == sv ? (std::abs(tu) < std::abs(tv) ? tu : tv) : tu + (su / (su - sv)) * (tv - tu);
    const Interval near = capsule_set(local(f, u), local(f, v), r);
    if (tc >= 0) reach.positive = std::min(reach.positive, std::max(0.0, near.lo));
    if (tc <= 0) reach.negative = std::min(reach.negative, std::max(0.0, -near.hi));
  }
  // (b) Discs around obstacle points near the split: the new segment from a (or b) stops where it first
  // touches one, which is where it meets a tangent from that end, unless the old segment already passes
  // through the disc.
  for (Vec2 w : {u, v}) {
    if (w == f.a || w == f.b) continue;
    const Local W = local(f, w);
    for (const double sigma : {f.h + W.s, f.h - W.s}) {
      if (sigma < -r || sigma > f.h + r) continue;
      const Interval touching = shadow_set(f.h, sigma, W, r);
      if (!(touching.lo < 0 && touching.hi > 0)) reach.block(touching);
    }
    if (u == v) break;
  }
}

}  // namespace selfsim::exclusion
