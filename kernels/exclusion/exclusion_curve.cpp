#include "kernels/exclusion/exclusion_curve.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "kernels/base/check.h"
#include "kernels/exclusion/curve_net.h"
#include "kernels/exclusion/original_rule.h"
#include "kernels/exclusion/start_check.h"

namespace selfsim::exclusion {

namespace {

// Working memory per point of the result, estimated: vertices and their links, about one and a half
// segments of 48 bytes, their grid cells (a 2^20-segment run peaks at 190 MiB, about 190 bytes a point).
// Counted against the budget in points of 16 bytes.
constexpr double working_points_per_point = 12;

// Seconds since `from`.
double since(std::chrono::steady_clock::time_point from) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - from).count();
}

void grow_breadth(Curves& c, const CurveOptions& opt, double total_splits, Progress& progress,
                  std::vector<LevelReport>& reports) {
  double r = opt.radius, done = 0;
  for (int level = 1; level <= opt.levels; ++level, r *= opt.factor) {
    const auto begun = std::chrono::steady_clock::now();
    LevelReport report;
    // Cells of 1.5 times the radius or the segments' mean length, whichever is larger (measured fastest
    // among 0.5 to 2 times), and not so small that a segment crossing the region fills millions of them.
    c.index(1.5 * std::max({r, c.mean_length(), 1e-6 * opt.radius}));
    const bool backwards = opt.scan == Scan::alternate && level % 2 == 0;
    for (std::size_t q = 0; q < c.curves(); ++q) {
      const std::size_t i = backwards ? c.curves() - 1 - q : q;
      const std::vector<std::uint32_t> chain = c.chain(i);
      const std::size_t n = c.closed(i) ? chain.size() : chain.size() - 1;
      for (std::size_t step = 0; step < n; ++step) {
        if ((report.splits & 1023) == 0) progress.step(done / total_splits);
        c.split(chain[backwards ? n - 1 - step : step], r, level, report);
        ++done;
      }
    }
    report.seconds = since(begun);
    reports.push_back(report);
  }
}

struct DepthRun {
  Curves& c;
  const CurveOptions& opt;
  double total_splits, done = 0;
  Progress& progress;
  std::vector<LevelReport>& reports;

  void split(std::uint32_t v, int depth, double r) {
    if (depth > opt.levels) return;
    if ((static_cast<std::size_t>(done) & 1023) == 0) progress.step(done / total_splits);
    const std::uint32_t p = c.split(v, r, depth, reports[depth - 1]);
    ++done;
    split(v, depth + 1, r * opt.factor);
    split(p, depth + 1, r * opt.factor);
  }
};

void grow_depth(Curves& c, const CurveOptions& opt, double total_splits, Progress& progress,
                std::vector<LevelReport>& reports) {
  const auto begun = std::chrono::steady_clock::now();
  reports.assign(opt.levels, LevelReport{});
  // One grid for the whole run, with cells about the last level's radius or segment length.
  const double last_r = opt.radius * std::pow(opt.factor, opt.levels - 1);
  c.index(std::max({last_r, c.mean_length() * std::ldexp(1.0, -opt.levels), 1e-6 * opt.radius}));
  DepthRun run{c, opt, total_splits, 0, progress, reports};
  for (std::size_t i = 0; i < c.curves(); ++i) {
    const std::vector<std::uint32_t> chain = c.chain(i);
    const std::size_t n = c.closed(i) ? chain.size() : chain.size() - 1;
    for (std::size_t k = 0; k < n; ++k) run.split(chain[k], 1, opt.radius);
  }
  if (!reports.empty()) reports.back().seconds = since(begun);
}

}  // namespace

void CurveOptions::validate() const {
  check_between(radius, 1e-300, 1e300, "option 'radius'");
  if (!(factor > 0 && factor <= 1)) throw Error("option 'factor' must be in (0, 1], got " + number_text(factor));
  check_range(levels, 0, 40, "option 'levels'");
}

std::size_t CurveResult::stuck() const { return total_stuck(levels); }

double curve_size(const Polyline& start, int levels) {
  double points = 0;
  for (std::size_t i = 0; i < start.paths(); ++i)
    points += static_cast<double>(start.path(i).size() - 1) * std::ldexp(1.0, levels) + 1;
  return points;
}

double working_size(const Polyline& start, int levels) {
  return curve_size(start, levels) * (1 + working_points_per_point);
}

namespace {

// The region and starts moved to the origin and scaled by a power of two to a size about 1: the closed-form
// limits square coordinates up to four times over, which would overflow or underflow far from that size.
struct Normalised {
  Vec2 centre;
  double scale;
  Vec2 to(Vec2 p) const { return scale * (p - centre); }
  Vec2 from(Vec2 q) const { return (1 / scale) * q + centre; }
};

Normalised normalised(const Region& region) {
  const BBox2 box = region.bbox();
  const double side = std::max(box.size().x, box.size().y);
  return {0.5 * (box.min + box.max), std::ldexp(1.0, -std::ilogb(side))};
}

}  // namespace

CurveResult exclusion_curve(const Region& region, const Polyline& start, const CurveOptions& opt, Progress& progress) {
  if (opt.exclusion == Mode::original) return original_curve(region, start, opt, progress);
  opt.validate();
  const double points = curve_size(start, opt.levels);
  check_budget(working_size(start, opt.levels), opt.budget,
               "levels = " + std::to_string(opt.levels) + " (" + count_text(points) + " curve points, each " +
                   count_text(1 + working_points_per_point) + " budget points with its working memory)");
  const Normalised n = normalised(region);
  const Region local = region.moved(n.centre, n.scale);
  Polyline local_start = start;
  for (Vec2& p : local_start.points) p = n.to(p);
  check_start(local, local_start, start);
  // The last level's radius must stay well above rounding at the region's size.
  check_last_radius(opt.radius, opt.factor, opt.levels, n.scale, 1e-12);
  CurveOptions local_opt = opt;
  local_opt.radius = opt.radius * n.scale;
  progress.start("exclusion curve");
  Curves c(local, local_start, local_opt, points);
  CurveResult result;
  const double splits = points - static_cast<double>(start.points.size());
  if (opt.order == Order::breadth)
    grow_breadth(c, local_opt, splits, progress, result.levels);
  else
    grow_depth(c, local_opt, splits, progress, result.levels);
  result.curve = c.result();
  // Back to the caller's coordinates, the start points exactly as given.
  const Field* made = result.curve.point_fields.find("level");
  for (std::size_t i = 0; i < result.curve.paths(); ++i) {
    const auto given = start.path(i);
    std::size_t k = 0;
    for (std::size_t j = result.curve.path_begin(i); j < result.curve.path_ends[i]; ++j)
      result.curve.points[j] = made->at(j) == 0 ? given[k++] : n.from(result.curve.points[j]);
  }
  if (!result.curve.finite()) throw Error("the exclusion curve has non-finite points");
  return result;
}

}  // namespace selfsim::exclusion
