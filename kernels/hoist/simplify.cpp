#include "kernels/hoist/simplify.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <utility>
#include <vector>

#include "kernels/base/check.h"
#include "kernels/base/error.h"

namespace selfsim::hoist {

namespace {

// Distance from p to the segment a–b (to a when a = b: a closed path's own chord). The projection is
// taken in units of the segment's larger coordinate difference: squared lengths of a curve 1e155 across
// overflow, and its points would all seem to project onto a.
double distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 d = b - a;
  const double unit = std::max(std::abs(d.x), std::abs(d.y));
  if (!(unit > 0)) return norm(p - a);
  const Vec2 du{d.x / unit, d.y / unit}, pu{(p.x - a.x) / unit, (p.y - a.y) / unit};
  const double w = std::clamp(dot(pu, du) / dot(du, du), 0.0, 1.0);
  return norm(p - (a + w * d));
}

// Marks the points of one path to keep. An explicit stack of runs, not recursion, so a path of a hundred
// million points cannot overflow the call stack. Plain Ramer–Douglas–Peucker splits a run at its farthest
// point, which on spirals and zigzags lands next to an end every time and makes the work quadratic (hours
// for a million points); here a run whose farthest point lies in its outer eighths is split at its middle
// instead. Every run still ends as a chord only when all its points lie within the tolerance of it, so the
// guarantee holds, the depth stays logarithmic, and the price is a few points plain RDP would not keep.
void mark(std::span<const Vec2> pts, double tolerance, std::vector<char>& keep, std::size_t offset,
          Progress& progress) {
  const std::size_t last = pts.size() - 1;
  std::vector<std::pair<std::size_t, std::size_t>> runs;
  keep[offset] = keep[offset + last] = 1;
  if (last >= 3 && pts.front() == pts.back()) {
    // A closed path keeps a triangle at least: the point farthest from its start, and the point farthest
    // from the chord between the two, so it never collapses to a back-and-forth segment.
    std::size_t far = 1;
    for (std::size_t i = 1; i < last; ++i)
      if (norm(pts[i] - pts[0]) > norm(pts[far] - pts[0])) far = i;
    std::size_t side = far == 1 ? 2 : 1;
    for (std::size_t i = 1; i < last; ++i)
      if (i != far && distance_to_segment(pts[i], pts[0], pts[far]) > distance_to_segment(pts[side], pts[0], pts[far]))
        side = i;
    const std::size_t lo = std::min(far, side), hi = std::max(far, side);
    keep[offset + lo] = keep[offset + hi] = 1;
    runs = {{0, lo}, {lo, hi}, {hi, last}};
  } else {
    runs = {{0, last}};
  }
  std::size_t work = 0;
  while (!runs.empty()) {
    const auto [a, b] = runs.back();
    runs.pop_back();
    if (b <= a + 1) continue;
    double farthest = -1;
    std::size_t at = a;
    for (std::size_t i = a + 1; i < b; ++i) {
      const double d = distance_to_segment(pts[i], pts[a], pts[b]);
      if (d > farthest) {
        farthest = d;
        at = i;
      }
    }
    if ((work += b - a) > (std::size_t{1} << 22)) {  // check for a stop as the work grows
      work = 0;
      if (progress.cancelled()) throw Cancelled();
    }
    if (farthest <= tolerance) continue;
    const std::size_t eighth = (b - a) / 8;
    if (at < a + eighth || at > b - eighth) at = a + (b - a) / 2;
    keep[offset + at] = 1;
    runs.push_back({a, at});
    runs.push_back({at, b});
  }
}

}  // namespace

Polyline simplify(const Polyline& c, double tolerance, Progress& progress) {
  if (!(tolerance > 0 && std::isfinite(tolerance)))
    throw Error("tolerance must be a positive distance in the curve's units, got " + number_text(tolerance));
  progress.start("simplify");
  std::vector<char> keep(c.points.size(), 0);
  for (std::size_t i = 0; i < c.paths(); ++i) {
    mark(c.path(i), tolerance, keep, c.path_begin(i), progress);
    progress.step(static_cast<double>(i + 1) / static_cast<double>(c.paths()));
  }
  Polyline out;
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < c.paths(); ++i) {
    for (std::size_t k = c.path_begin(i); k < c.path_ends[i]; ++k)
      if (keep[k]) kept.push_back(k);
    out.path_ends.push_back(kept.size());
  }
  out.points.resize(kept.size());
  for (std::size_t k = 0; k < kept.size(); ++k) out.points[k] = c.points[kept[k]];
  out.point_fields = picked_fields<std::size_t>(c.point_fields, kept);
  out.cell_fields = c.cell_fields;
  return out;
}

}  // namespace selfsim::hoist
