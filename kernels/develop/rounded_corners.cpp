#include "kernels/develop/rounded_corners.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "kernels/base/check.h"
#include "kernels/base/error.h"
#include "kernels/develop/level_stack.h"

namespace selfsim::develop {

namespace {

// Arc segments for a turn of phi radians: `samples` a quarter turn, at least one.
int arc_segments(double phi, int samples) {
  return std::max(1, static_cast<int>(std::ceil(phi / (std::numbers::pi / 2) * samples - 1e-9)));
}

// Appends the rounding of the corner at p between segments from `prev` and to `next` to the path that
// begins at out[path_begin].
void round_corner(Vec2 prev, Vec2 p, Vec2 next, int samples, std::size_t path_begin, PointArray<Vec2>& out) {
  const Vec2 in = p - prev, to = next - p;
  const double a = norm(in), b = norm(to);
  // Divided, not multiplied by 1 / a: for a curve 1e-320 across that reciprocal overflows.
  const Vec2 u{in.x / a, in.y / a}, v{to.x / b, to.y / b};
  const double phi = std::atan2(std::abs(cross(u, v)), dot(u, v));  // turning angle in [0, π]
  if (phi < 1e-9 || phi > std::numbers::pi - 1e-9) {
    out.push_back(p);  // straight on, or a U-turn: no arc
    return;
  }
  const double d = std::min(a, b) / 2;           // tangent points at half the shorter segment from the corner
  const double r = d / std::tan(phi / 2);        // the arc's radius
  const double side = cross(u, v) > 0 ? 1 : -1;  // turning left: the centre is on the left
  const Vec2 start = p - d * u, normal{-u.y * side, u.x * side};
  const Vec2 centre = start + r * normal;
  const int n = arc_segments(phi, samples);
  // The arc starts where the previous one ended when the segment between them is as short as the corners'
  // tangent lengths allow (equal segments): one point there, not two a rounding error apart.
  const bool joined = out.size() > path_begin && norm(out.back() - start) <= 1e-12 * d;
  for (int k = joined ? 1 : 0; k <= n; ++k) {
    const double t = side * phi * k / n;  // rotate start about the centre by t
    const Vec2 s = start - centre;
    out.push_back(centre + Vec2{s.x * std::cos(t) - s.y * std::sin(t), s.x * std::sin(t) + s.y * std::cos(t)});
  }
}

}  // namespace

void RoundOptions::validate() const { check_range(samples, 1, 1024, "option 'samples'"); }

double rounded_size(const Polyline& c, const RoundOptions& opt) {
  // At most samples·2 + 1 points a corner (a turn is at most half a circle), plus an open path's ends.
  return static_cast<double>(c.points.size()) * (2.0 * opt.samples + 1) + 2.0 * static_cast<double>(c.paths());
}

Polyline rounded_corners(const Polyline& c, const RoundOptions& opt, Progress& progress) {
  opt.validate();
  check_budget(rounded_size(c, opt), opt.budget, "rounded");
  Polyline out;
  // A corner makes up to 2·samples + 1 points: look for a stop about every 65,536 points made.
  const std::size_t every = std::max<std::size_t>(1, 65536 / (2 * static_cast<std::size_t>(opt.samples) + 1));
  for (std::size_t i = 0; i < c.paths(); ++i) {
    if ((i & 0xff) == 0) progress.step(static_cast<double>(i) / static_cast<double>(c.paths()));
    const auto p = c.path(i);
    for (std::size_t k = 0; k + 1 < p.size(); ++k)
      if (p[k] == p[k + 1])
        throw Error("path " + std::to_string(i + 1) + " has a zero-length segment at its point " +
                    std::to_string(k + 1) + ": a corner there has no direction to round");
    if (p.size() < 3) {
      for (Vec2 q : p) out.points.push_back(q);
    } else if (p.size() >= 4 && closed_path(p)) {
      const std::size_t n = p.size() - 1;  // corners 0..n-1, the last point repeats the first
      const std::size_t begin = out.points.size();
      for (std::size_t k = 0; k < n; ++k) {
        if (k % every == every - 1 && progress.cancelled()) throw Cancelled();
        round_corner(p[(k + n - 1) % n], p[k], p[k + 1], opt.samples, begin, out.points);
      }
      // Closed again: the last arc ends where the first began (to rounding, then exactly), or a straight
      // segment joins them.
      if (norm(out.points.back() - out.points[begin]) <= 1e-12 * norm(p[1] - p[0]))
        out.points.back() = out.points[begin];
      else
        out.points.push_back(out.points[begin]);
    } else {
      const std::size_t begin = out.points.size();
      out.points.push_back(p.front());
      for (std::size_t k = 1; k + 1 < p.size(); ++k) {
        if (k % every == 0 && progress.cancelled()) throw Cancelled();
        round_corner(p[k - 1], p[k], p[k + 1], opt.samples, begin, out.points);
      }
      out.points.push_back(p.back());
    }
    out.close_path();
  }
  for (const Field& f : c.point_fields.list)
    if (f.uniform) out.point_fields.set(f);
  out.cell_fields = c.cell_fields;
  if (!out.finite()) throw Error("rounded corners are not finite (the curve is too large to round)");
  return out;
}

}  // namespace selfsim::develop
