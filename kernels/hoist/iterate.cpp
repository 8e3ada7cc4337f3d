#include "kernels/hoist/iterate.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "kernels/base/check.h"
#include "kernels/hoist/hoist.h"
#include "kernels/hoist/multiply.h"

namespace selfsim::hoist {

void IterateOptions::validate() const {
  check_between(multiplicity, 1, 1e6, "option 'multiplicity'");
  check_range(generations, 0, 64, "option 'generations'");
}

double iterated_points(std::size_t n, const IterateOptions& opt) {
  double points = static_cast<double>(n), previous = 0;
  for (int g = 0; g < opt.generations; ++g) {
    previous = points;
    points = multiplied_points(static_cast<std::size_t>(std::min(points, 9e15)), opt.multiplicity);
    if (!(points < 1e300)) break;  // far past any budget already
  }
  return points + previous;
}

Polyline iterate(const Polyline& p, const IterateOptions& opt, Progress& progress) {
  opt.validate();
  const BaseCurve base(p);
  const std::string what =
      "generations " + std::to_string(opt.generations) + " at multiplicity " + number_text(opt.multiplicity) +
      (opt.multiplicity == std::floor(opt.multiplicity) ? "" : " (an estimate for a fractional multiplicity)");
  check_budget(iterated_points(p.points.size(), opt), opt.budget, what);
  progress.start("iterating");
  Polyline c;
  c.points = p.points;
  c.close_path();
  if (const Field* t = p.point_fields.find("t")) c.point_fields.set(*t);
  for (int g = 0; g < opt.generations; ++g) {
    ProgressStage stage(progress, static_cast<double>(g) / opt.generations,
                        static_cast<double>(g + 1) / opt.generations);
    MultiplyOptions m{opt.multiplicity, opt.transforms, opt.budget};
    m.budget.held += static_cast<double>(c.points.size());  // C is held while the next generation is made
    c = hoist_onto(multiply(c, m, stage), base, opt.boundary, stage);
    progress.fraction(static_cast<double>(g + 1) / opt.generations);
  }
  c.point_fields.set(uniform_int("generation", opt.generations));
  return c;
}

}  // namespace selfsim::hoist
