#include "kernels/substitute/substitute.h"

#include <cmath>
#include <string>

#include "kernels/base/budget.h"
#include "kernels/base/check.h"
#include "kernels/base/error.h"
#include "kernels/geom/similarity.h"

namespace selfsim::substitute {

namespace {

struct Substitution {
  std::vector<Similarity2> child;    // generator segment i as a map of the unit segment, transform included
  std::vector<bool> child_reversed;  // true where that copy is walked backwards
  PointArray<Vec2>& out;
  Progress& progress;
  double total;

  // Appends the end points of M's copy, `level` rounds deep, walking it forwards or backwards.
  void emit(const Similarity2& m, int level, bool forward) {
    if (level == 0) {
      out.push_back(m(forward ? Vec2{1, 0} : Vec2{0, 0}));
      if (out.size() % (1u << 20) == 0) progress.step(static_cast<double>(out.size()) / total);
      return;
    }
    const std::size_t n = child.size();
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t i = forward ? k : n - 1 - k;
      emit(m.after(child[i]), level - 1, forward != child_reversed[i]);
    }
  }
};

}  // namespace

void SubstituteOptions::validate(std::size_t generator_segments) const {
  check_range(levels, 0, 64, "option 'levels'");
  if (!transforms.empty() && transforms.size() != generator_segments)
    throw Error("option 'transforms' must have one entry per generator segment (" + std::to_string(generator_segments) +
                "), got " + std::to_string(transforms.size()));
}

Polyline substitute(const Polyline& path, const Polyline& generator, const SubstituteOptions& opt, Progress& progress) {
  if (path.segments() < 1) throw Error("option 'path' must have at least one segment");
  if (generator.paths() != 1 || generator.segments() < 1)
    throw Error("option 'generator' must be a single path with at least one segment");
  const auto g = generator.path(0);
  const Vec2 g0 = g.front(), g1 = g.back();
  if (norm(g0) > 1e-9 || norm(g1 - Vec2{1, 0}) > 1e-9) throw Error("option 'generator' must run from (0,0) to (1,0)");
  if (!path.finite() || !generator.finite()) throw Error("option 'path'/'generator' has non-finite coordinates");
  const std::size_t n = g.size() - 1;
  opt.validate(n);

  const double segments = static_cast<double>(path.segments()) * std::pow(static_cast<double>(n), opt.levels);
  const double points = segments + static_cast<double>(path.paths());
  check_budget(points, opt.budget, "levels " + std::to_string(opt.levels));

  Polyline result;
  result.point_fields.set(uniform_int("level", opt.levels));
  result.points.reserve(static_cast<std::size_t>(points));
  progress.start("substitute");
  Substitution s{{}, {}, result.points, progress, points};
  for (std::size_t i = 0; i < n; ++i) {
    const SegmentTransform t = opt.transforms.empty() ? SegmentTransform::Identity : opt.transforms[i];
    s.child.push_back(Similarity2::from_segment(g[i], g[i + 1]).after(unit_map(t)));
    s.child_reversed.push_back(walks_backwards(t));
  }
  // Every path of the input is substituted on its own and stays a path of the result, with its cell fields
  // (a group's `curve`, a member's colour).
  for (std::size_t i = 0; i < path.paths(); ++i) {
    const auto p = path.path(i);
    result.points.push_back(p.front());
    for (std::size_t k = 0; k + 1 < p.size(); ++k) s.emit(Similarity2::from_segment(p[k], p[k + 1]), opt.levels, true);
    result.close_path();
  }
  result.cell_fields = path.cell_fields;
  if (!result.finite()) throw Error("substitution produced non-finite coordinates");
  return result;
}

}  // namespace selfsim::substitute
