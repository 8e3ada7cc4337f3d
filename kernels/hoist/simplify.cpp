#include "kernels/hoist/simplify.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <utility>
#include <vector>

#include "kernels/geom/check.h"
#include "kernels/geom/error.h"

namespace selfsim::hoist {

namespace {

// Distance from p to the segment a–b (to a when a = b: a closed path's own chord).
double distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 d = b - a;
  const double len2 = dot(d, d);
  if (!(len2 > 0)) return norm(p - a);
  const double w = std::clamp(dot(p - a, d) / len2, 0.0, 1.0);
  return norm(p - (a + w * d));
}

// Marks the points of one path [begin, end) to keep. An explicit stack of runs, not recursion, so a path of
// a hundred million points cannot overflow the call stack.
void mark(std::span<const Vec2> pts, double tolerance, std::vector<char>& keep, std::size_t offset,
          Progress& progress) {
  std::vector<std::pair<std::size_t, std::size_t>> runs{{0, pts.size() - 1}};
  std::size_t work = 0;
  keep[offset] = keep[offset + pts.size() - 1] = 1;
  while (!runs.empty()) {
    const auto [a, b] = runs.back();
    runs.pop_back();
    if (b <= a + 1) continue;
    double far = -1;
    std::size_t at = a;
    for (std::size_t i = a + 1; i < b; ++i)
      if (const double d = distance_to_segment(pts[i], pts[a], pts[b]); d > far) far = d, at = i;
    // A worst case (a spiral) looks at every point once per kept point: check for a stop as the work grows.
    if ((work += b - a) > (std::size_t{1} << 22)) {
      work = 0;
      if (progress.cancelled()) throw Cancelled();
    }
    if (far <= tolerance) continue;
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
  for (const Field& f : c.point_fields.list) {
    if (f.uniform) {
      out.point_fields.set(f);
      continue;
    }
    Field g{f.name, f.components, f.data, false};
    std::visit(
        [&](auto& v) {
          const auto& src = v;
          std::remove_cvref_t<decltype(v)> picked;
          picked.reserve(kept.size() * static_cast<std::size_t>(f.components));
          for (std::size_t k : kept)
            for (int j = 0; j < f.components; ++j)
              picked.push_back(src[k * static_cast<std::size_t>(f.components) + static_cast<std::size_t>(j)]);
          v = std::move(picked);
        },
        g.data);
    out.point_fields.set(std::move(g));
  }
  out.cell_fields = c.cell_fields;
  return out;
}

}  // namespace selfsim::hoist
