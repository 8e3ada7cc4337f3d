#include "kernels/hoist/spline.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "kernels/base/check.h"
#include "kernels/base/error.h"
#include "kernels/geom/similarity.h"

namespace selfsim::hoist {

namespace {

constexpr int min_depth = 2, max_depth = 16;

// One cubic span through four consecutive (extended) control points, as position and derivative at u in [0, 1].
struct Span {
  Vec2 p0, p1, p2, p3;
  SplineKind kind;

  Vec2 at(double u) const {
    const double v = 1 - u;
    if (kind == SplineKind::BSpline)
      return (v * v * v * p0 + (3 * u * u * u - 6 * u * u + 4) * p1 + (-3 * u * u * u + 3 * u * u + 3 * u + 1) * p2 +
              u * u * u * p3) *
             (1.0 / 6);
    // Catmull-Rom: the cubic Hermite curve from p1 to p2 with tangents (p2 − p0)/2 and (p3 − p1)/2.
    const Vec2 m1 = 0.5 * (p2 - p0), m2 = 0.5 * (p3 - p1);
    return (2 * u * u * u - 3 * u * u + 1) * p1 + (u * u * u - 2 * u * u + u) * m1 + (-2 * u * u * u + 3 * u * u) * p2 +
           (u * u * u - u * u) * m2;
  }
  Vec2 derivative(double u) const {
    if (kind == SplineKind::BSpline)
      return 0.5 * (-(1 - u) * (1 - u) * p0 + (3 * u * u - 4 * u) * p1 + (-3 * u * u + 2 * u + 1) * p2 + u * u * p3);
    const Vec2 m1 = 0.5 * (p2 - p0), m2 = 0.5 * (p3 - p1);
    return (6 * u * u - 6 * u) * p1 + (3 * u * u - 4 * u + 1) * m1 + (-6 * u * u + 6 * u) * p2 +
           (3 * u * u - 2 * u) * m2;
  }
};

double distance_to_chord(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 d = b - a;
  const double len = norm(d);
  return len > 0 ? std::abs(cross(d, p - a)) / len : norm(p - a);
}

struct Sampler {
  const Span& span;
  double flatness;
  PointArray<Vec2>& points;
  std::vector<double>& params;  // span parameter of each sample, for the tangents
  const PointBudget& budget;

  // Appends the samples in (a, b], b's point included.
  void refine(double a, Vec2 pa, double b, Vec2 pb, int depth) {
    const double m = 0.5 * (a + b);
    const Vec2 pm = span.at(m);
    if (depth < max_depth && (depth < min_depth || distance_to_chord(pm, pa, pb) > flatness)) {
      refine(a, pa, m, pm, depth + 1);
      refine(m, pm, b, pb, depth + 1);
      return;
    }
    if (pb == points.back()) return;  // a degenerate span (repeated control points): nothing new
    if (static_cast<double>(points.size()) + 1 > budget.left())
      check_budget(static_cast<double>(points.size()) + 1, budget,
                   "sampling the spline at flatness " + number_text(flatness));
    points.push_back(pb);
    params.push_back(b);
  }
};

}  // namespace

void SplineOptions::validate() const {
  if (points.size() < 3)
    throw Error("option 'points' needs at least 3 control points (two give only the straight segment), got " +
                std::to_string(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!is_finite(points[i])) throw Error("option 'points': point " + std::to_string(i + 1) + " is not finite");
  // Normalising maps the ends a unit apart: ends closer than a billionth of the control polygon's size would
  // blow the curve up by as much (and equal ends cannot be mapped at all).
  const Vec2 size = bbox_of<Vec2>(points).size();
  const double apart = norm(points.back() - points.front());
  if (!(apart > 0) || (normalize && !(apart > 1e-9 * std::max(size.x, size.y))))
    throw Error("option 'points': the first and last control points " +
                std::string(points.back() == points.front() ? "coincide" : "almost coincide") +
                " (a base curve runs from (0,0) to (1,0))");
  if (!normalize && (norm(points.front()) > 1e-12 || norm(points.back() - Vec2{1, 0}) > 1e-12))
    throw Error("option 'points' must start at (0,0) and end at (1,0), got (" + number_text(points.front().x) + ", " +
                number_text(points.front().y) + ") to (" + number_text(points.back().x) + ", " +
                number_text(points.back().y) + ") (or set normalize = true)");
  check_between(flatness, 1e-9, 0.1, "option 'flatness'");
}

Polyline sample_spline(const SplineOptions& opt, Progress& progress) {
  opt.validate();
  progress.start("sampling the spline");
  std::vector<Vec2> p = opt.points;
  if (opt.normalize) {
    // Brought to unit size first: the similarity's complex division squares the coordinates.
    const double big = largest_coordinate(bbox_of<Vec2>(p));
    for (Vec2& q : p) q = (1 / big) * q;
    const Similarity2 to_unit = Similarity2::to_unit(p.front(), p.back());
    for (Vec2& q : p) q = to_unit(q);
  }
  p.front() = {0, 0};  // exactly, whatever rounding normalising left
  p.back() = {1, 0};
  std::vector<Vec2> ext;
  ext.reserve(p.size() + 2);
  ext.push_back(2 * p[0] - p[1]);
  ext.insert(ext.end(), p.begin(), p.end());
  ext.push_back(2 * p.back() - p[p.size() - 2]);

  Polyline out;
  std::vector<Vec2> tangents;
  out.points.push_back(p.front());
  const std::size_t spans = p.size() - 1;
  for (std::size_t j = 0; j < spans; ++j) {
    const Span span{ext[j], ext[j + 1], ext[j + 2], ext[j + 3], opt.kind};
    std::vector<double> params;
    if (j == 0) tangents.push_back(span.derivative(0));
    Sampler{span, opt.flatness, out.points, params, opt.budget}.refine(0, span.at(0), 1, span.at(1), 0);
    for (std::size_t k = 0; k < params.size(); ++k) tangents.push_back(span.derivative(params[k]));
    progress.step(static_cast<double>(j + 1) / static_cast<double>(spans));
  }
  out.points.back() = {1, 0};
  out.close_path();

  if (!out.finite()) throw Error("the spline's points overflow: its control points are too large (scale them down)");
  // Unit tangents; a zero derivative (a cusp, where control points repeat) takes the direction between the
  // neighbouring samples, which are distinct (repeats are not sampled).
  std::vector<double> tangent_values, t_values;
  tangent_values.reserve(2 * tangents.size());
  const std::size_t n = out.points.size();
  for (std::size_t i = 0; i < n; ++i) {
    Vec2 d = tangents[i];
    if (!(norm(d) > 1e-12)) d = out.points[std::min(i + 1, n - 1)] - out.points[i > 0 ? i - 1 : 0];
    d = (1 / norm(d)) * d;
    tangent_values.push_back(d.x);
    tangent_values.push_back(d.y);
  }
  const double length = out.length();
  if (!std::isfinite(length))
    throw Error("the spline's length overflows: its control points are too large (scale them down)");
  if (!(length > 0)) throw Error("the spline has no length");
  double s = 0;
  t_values.push_back(0);
  for (std::size_t i = 1; i < n; ++i) {
    s += norm(out.points[i] - out.points[i - 1]);
    t_values.push_back(s / length);
  }
  t_values.back() = 1;
  out.point_fields.set(real_field("tangent", std::move(tangent_values), 2));
  out.point_fields.set(real_field("t", std::move(t_values)));
  return out;
}

}  // namespace selfsim::hoist
