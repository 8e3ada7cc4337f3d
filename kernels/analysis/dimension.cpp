#include "kernels/analysis/dimension.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "kernels/base/check.h"
#include "kernels/base/error.h"
#include "kernels/geom/segment_grid.h"

namespace selfsim::analysis {

LineFit fit_line(std::vector<double> x, std::vector<double> y) {
  const std::size_t n = x.size();
  if (n < 2 || y.size() != n) throw Error("a line fit needs at least two points");
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < n; ++i) mx += x[i] / n, my += y[i] / n;
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < n; ++i) sxx += (x[i] - mx) * (x[i] - mx), sxy += (x[i] - mx) * (y[i] - my);
  if (!(sxx > 0)) throw Error("a line fit needs points at two different x at least");
  LineFit f;
  f.slope = sxy / sxx;
  f.intercept = my - f.slope * mx;
  if (n > 2) {
    double residuals = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double e = y[i] - (f.intercept + f.slope * x[i]);
      residuals += e * e;
    }
    f.error = std::sqrt(residuals / static_cast<double>(n - 2) / sxx);
    f.has_error = true;
  }
  f.x = std::move(x);
  f.y = std::move(y);
  return f;
}

Dimension length_scaling(const Polyline& c, int from, int to) {
  const Field* field = c.point_fields.find("level");
  if (field == nullptr)
    throw Error(
        "length scaling needs the point field 'level' (the level each point was made at), which "
        "exclusion.curve gives; this curve has none");
  int top = 0;
  for (std::size_t i = 0; i < c.points.size(); ++i) top = std::max(top, static_cast<int>(field->at(i)));
  if (to < 0) to = top;
  if (from < 0 || from > to || to > top)
    throw Error("levels from " + std::to_string(from) + " to " + std::to_string(to) + " are not within the curve's " +
                "levels 0 to " + std::to_string(top));
  if (to - from < 1) throw Error("length scaling needs at least two levels, got only level " + std::to_string(from));
  // Each path's length at each level: the segments between consecutive points of level <= N.
  std::vector<double> length(top + 1, 0.0);
  for (std::size_t p = 0; p < c.paths(); ++p) {
    const std::size_t begin = c.path_begin(p), end = c.path_ends[p];
    for (int n = 0; n <= top; ++n) {
      std::size_t last = end;
      for (std::size_t i = begin; i < end; ++i) {
        if (field->at(i) > n) continue;
        if (last != end) length[n] += norm(c.points[i] - c.points[last]);
        last = i;
      }
    }
  }
  if (!(length[0] > 0)) throw Error("length scaling needs a start (level 0) of positive length");
  Dimension d;
  std::vector<double> x, y;
  for (int n = from; n <= to; ++n) {
    if (!(length[n] > 0)) throw Error("level " + std::to_string(n) + " has zero length");
    x.push_back(std::log(std::ldexp(1.0, n) / length[0]));
    y.push_back(std::log(length[n]));
    d.steps.push_back(n);
  }
  d.fit = fit_line(std::move(x), std::move(y));
  d.dimension = d.fit.slope + 1;
  return d;
}

Dimension box_counting(const Polyline& c, int from, int to, Progress& progress) {
  check_range(from, 0, 11, "the first box step");
  check_range(to, 0, 11, "the last box step");
  if (to - from < 1)
    throw Error("box counting needs at least two box sizes (steps " + std::to_string(from) + " to " +
                std::to_string(to) + ")");
  if (c.segments() == 0) throw Error("box counting needs a curve with segments");
  const BBox2 box = c.bbox();
  const double side = std::max(box.size().x, box.size().y);
  if (!(side > 0) || !std::isfinite(side)) throw Error("box counting needs a curve with a finite, non-zero extent");
  Dimension d;
  std::vector<double> x, y;
  for (int k = from; k <= to; ++k) {
    progress.step(static_cast<double>(k - from) / (to - from + 1));
    // The boxes of side side / 2^k over the curve's square, every segment listed in those it passes through.
    const double s = side / std::ldexp(1.0, k);
    const BBox2 square{box.min, box.min + Vec2::all(side * (1 - 1e-12))};
    SegmentGrid grid(square, s);
    for (std::size_t p = 0; p < c.paths(); ++p) {
      const auto path = c.path(p);
      for (std::size_t i = 0; i + 1 < path.size(); ++i) grid.insert(0, path[i], path[i + 1]);
    }
    x.push_back(k * std::log(2.0));
    y.push_back(std::log(static_cast<double>(grid.occupied())));
    d.steps.push_back(k);
  }
  d.fit = fit_line(std::move(x), std::move(y));
  d.dimension = d.fit.slope;
  return d;
}

}  // namespace selfsim::analysis
