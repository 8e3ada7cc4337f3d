#include "kernels/exclusion/original_rule.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "kernels/base/check.h"
#include "kernels/exclusion/original_chains.h"
#include "kernels/exclusion/start_check.h"

namespace selfsim::exclusion {

namespace {

// Working memory per point of the result, measured: a 2^18-segment run peaks at 92 MiB, about 370 bytes
// a point (vertex and links, up to three segment records a point by a level's end, grid entries of 40
// bytes in two or three cells each, twice while they are packed again). In points of 16 bytes.
constexpr double working_points_per_point = 24;

double since(std::chrono::steady_clock::time_point from) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - from).count();
}

}  // namespace

CurveResult original_curve(const Region& region, const Polyline& start, const CurveOptions& opt, Progress& progress) {
  opt.validate();
  if (opt.order != Order::breadth)
    throw Error("option 'order' must be \"breadth\" with the original rule (his program splits level by level)");
  const double points = curve_size(start, opt.levels);
  check_budget(points * (1 + working_points_per_point), opt.budget,
               "levels = " + std::to_string(opt.levels) + " (" + count_text(points) + " curve points, each " +
                   count_text(1 + working_points_per_point) + " budget points with its working memory)");
  check_start(region, start, start);
  // A power of two, so that the arithmetic is his bit for bit, bringing the largest coordinate to about 1.
  const double scale = std::ldexp(1.0, -std::ilogb(largest_coordinate(region.bbox())));
  // His radius shrinks after every curve of every level: the last split's radius must stay well above
  // rounding.
  const int shrinks = static_cast<int>(start.paths()) * opt.levels - 1;
  const double last = opt.radius * std::pow(opt.factor, std::max(shrinks, 0));
  if (opt.levels > 0 && !(last * scale >= 1e-12))
    throw Error("option 'radius' falls to " + number_text(last) + " by level " + std::to_string(opt.levels) +
                " (factor " + number_text(opt.factor) + ", once per curve per level), below 1e-12 of the " +
                "region's largest coordinate: raise 'radius' or 'factor', or lower 'levels'");
  progress.start("exclusion curve");
  original::Chains c(region, start, scale, opt.brute_force, points);
  CurveResult result;
  const double total = points - static_cast<double>(start.points.size());
  double done = 0, r = opt.radius * scale;
  for (int level = 1; level <= opt.levels; ++level) {
    const auto begun = std::chrono::steady_clock::now();
    LevelReport report;
    c.begin_level(r);
    const bool backwards = opt.scan == Scan::alternate && level % 2 == 0;
    for (std::size_t i = 0; i < c.curves(); ++i) {
      // The vertices at the pass's start, each splitting its own segment once (points made in the pass
      // are not split in it); backwards from the last vertex, a closed curve's closing segment first.
      std::vector<std::uint32_t> chain = c.chain(i);
      if (backwards) std::reverse(chain.begin(), chain.end());
      for (std::uint32_t v : chain) {
        if (!c.has_next(v)) continue;
        if ((report.splits & 1023) == 0) progress.step(done / total);
        if (c.split(v, r, level) == 0) ++report.stuck;
        ++report.splits;
        ++done;
      }
      r *= opt.factor;
    }
    report.seconds = since(begun);
    result.levels.push_back(report);
  }
  result.curve = c.result(start, scale);
  if (!result.curve.finite()) throw Error("the exclusion curve has non-finite points");
  return result;
}

}  // namespace selfsim::exclusion
