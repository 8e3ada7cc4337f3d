#include "kernels/hoist/base_curve.h"

#include <algorithm>
#include <cmath>

#include "kernels/base/error.h"

namespace selfsim::hoist {

namespace {

Vec2 unit(Vec2 v) { return (1 / norm(v)) * v; }

}  // namespace

BaseCurve::BaseCurve(const Polyline& p) {
  if (p.paths() != 1) throw Error("the base curve must be a single path, got " + std::to_string(p.paths()));
  const auto pts = p.path(0);
  if (pts.size() < 2) throw Error("the base curve needs at least 2 points");
  if (!p.finite()) throw Error("the base curve has non-finite points");
  if (norm(pts.front()) > 1e-9 || norm(pts.back() - Vec2{1, 0}) > 1e-9)
    throw Error("the base curve must run from (0,0) to (1,0) (bspline{} and catmull_rom{} curves do)");
  const Field* tangent = p.point_fields.find("tangent");
  if (tangent != nullptr && tangent->components != 2) tangent = nullptr;
  // Samples closer than rounding add nothing and would make a zero-length interval: dropped.
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (!points_.empty() && pts[i] == points_.back()) continue;
    points_.push_back(pts[i]);
    if (tangent == nullptr) continue;
    Vec2 d{tangent->at(i, 0), tangent->at(i, 1)};
    // A sample without a usable tangent takes the direction between its neighbours.
    if (!(norm(d) > 0) || !is_finite(d)) d = pts[std::min(i + 1, pts.size() - 1)] - pts[i > 0 ? i - 1 : 0];
    if (!(norm(d) > 0) || !is_finite(d)) d = {1, 0};
    tangents_.push_back(unit(d));
  }
  if (points_.size() < 2) throw Error("the base curve has no length");
  t_.push_back(0);
  for (std::size_t i = 1; i < points_.size(); ++i) t_.push_back(t_.back() + norm(points_[i] - points_[i - 1]));
  length_ = t_.back();
  if (!(length_ > 0) || !std::isfinite(length_)) throw Error("the base curve's length is not a positive number");
  for (double& t : t_) t /= length_;
  t_.back() = 1;
}

Frame BaseCurve::inside(double t) const {
  // The interval [t_i, t_i+1] holding t, by bisection.
  const auto it = std::upper_bound(t_.begin() + 1, t_.end() - 1, t);
  const std::size_t i = static_cast<std::size_t>(it - t_.begin()) - 1;
  const double w = std::clamp((t - t_[i]) / (t_[i + 1] - t_[i]), 0.0, 1.0);
  if (tangents_.empty()) return {lerp(points_[i], points_[i + 1], w), unit(points_[i + 1] - points_[i])};
  Vec2 d = lerp(tangents_[i], tangents_[i + 1], w);
  // Opposite tangents at the two ends of an interval (a cusp) average to nothing: the chord then.
  if (!(norm(d) > 1e-12)) d = points_[i + 1] - points_[i];
  return {lerp(points_[i], points_[i + 1], w), unit(d)};
}

Frame BaseCurve::at(double t, Boundary mode) const {
  if (t >= 0 && t <= 1) return inside(t);
  if (mode == Boundary::Clamp) return {t < 0 ? Vec2{length_ * t, 0} : Vec2{1 + length_ * (t - 1), 0}, {1, 0}};
  const double k = std::floor(t);
  const double u = t - k;
  const Vec2 shift{k, 0};
  const bool odd = std::fmod(std::abs(k), 2.0) == 1;
  if (!odd || mode == Boundary::Repeat) {
    const Frame f = inside(u);
    return {f.position + shift, f.tangent};
  }
  if (mode == Boundary::ReflectX) {
    const Frame f = inside(u);
    return {conj(f.position) + shift, conj(f.tangent)};
  }
  // Reflect Y and Rotate walk P backwards: the copy at u is P at 1 − u, mirrored left to right (Reflect Y)
  // or turned half a circle about (1/2, 0) (Rotate), so it still runs from (k, 0) to (k + 1, 0).
  const Frame f = inside(1 - u);
  if (mode == Boundary::ReflectY) return {Vec2{1 - f.position.x, f.position.y} + shift, conj(f.tangent)};
  return {Vec2{1, 0} - f.position + shift, f.tangent};
}

}  // namespace selfsim::hoist
