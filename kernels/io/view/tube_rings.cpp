#include "kernels/io/view/tube_rings.h"

#include <cmath>
#include <numbers>

namespace selfsim::io {

namespace {

using V = std::array<double, 3>;

V sub(const V& a, const V& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V add(const V& a, const V& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
V scale(const V& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
double dot(const V& a, const V& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V cross(const V& a, const V& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
bool unit(V& a) {
  const double n = std::sqrt(dot(a, a));
  if (!(n > 0) || !std::isfinite(n)) return false;
  a = scale(a, 1 / n);
  return true;
}

}  // namespace

std::size_t tube_rings(std::span<const V> points, std::span<const double> radii, int sides, std::uint32_t first,
                       std::vector<V>& positions, std::vector<std::uint32_t>& triangles) {
  const std::size_t n = points.size();
  if (n < 2 || sides < 3) return 0;
  // Each point's direction along the line: the mean of its segments' (a repeated point takes its neighbour's).
  std::vector<V> along(n);
  bool any = false;
  for (std::size_t i = 0; i < n; ++i) {
    V in = i > 0 ? sub(points[i], points[i - 1]) : V{}, out = i + 1 < n ? sub(points[i + 1], points[i]) : V{};
    unit(in);
    unit(out);
    along[i] = add(in, out);
    if (!unit(along[i])) along[i] = i + 1 < n ? out : in;
    any = any || dot(along[i], along[i]) > 0;
  }
  if (!any) return 0;
  for (std::size_t i = 1; i < n; ++i)  // a point between coincident ones: the direction before it
    if (dot(along[i], along[i]) == 0) along[i] = along[i - 1];
  for (std::size_t i = n - 1; i-- > 0;)
    if (dot(along[i], along[i]) == 0) along[i] = along[i + 1];
  // The first ring's frame: any perpendicular, from the axis least along the line.
  const V& t0 = along[0];
  const int least = std::abs(t0[0]) <= std::abs(t0[1]) && std::abs(t0[0]) <= std::abs(t0[2]) ? 0
                    : std::abs(t0[1]) <= std::abs(t0[2])                                     ? 1
                                                                                             : 2;
  V axis{};
  axis[least] = 1;
  V normal = cross(t0, axis);
  unit(normal);
  for (std::size_t i = 0; i < n; ++i) {
    // Carried on: the last normal made perpendicular to this point's direction.
    V carried = sub(normal, scale(along[i], dot(normal, along[i])));
    if (unit(carried)) normal = carried;
    const V binormal = cross(along[i], normal);
    const double r = radii[i];
    for (int k = 0; k < sides; ++k) {
      const double a = 2 * std::numbers::pi * k / sides;
      positions.push_back(add(points[i], add(scale(normal, r * std::cos(a)), scale(binormal, r * std::sin(a)))));
    }
  }
  const auto s = static_cast<std::uint32_t>(sides);
  for (std::uint32_t i = 0; i + 1 < n; ++i)
    for (std::uint32_t k = 0; k < s; ++k) {
      const std::uint32_t a = first + i * s + k, b = first + i * s + (k + 1) % s, c = a + s, d = b + s;
      triangles.insert(triangles.end(), {a, b, d, a, d, c});
    }
  return n * static_cast<std::size_t>(sides);
}

}  // namespace selfsim::io
