#include "kernels/exclusion/discs.h"

#include <cmath>
#include <string>

#include "kernels/base/check.h"
#include "kernels/base/error.h"

namespace selfsim::exclusion {

Polyline exclusion_discs(const Polyline& curve, const DiscOptions& opt, Progress& progress) {
  check_between(opt.radius, 1e-300, 1e300, "option 'radius'");
  if (!(opt.factor > 0 && opt.factor <= 1))
    throw Error("option 'factor' must be in (0, 1], got " + number_text(opt.factor));
  check_range(opt.samples, 3, 4096, "option 'samples'");
  check_range(opt.level, -1, 40, "option 'level'");
  const Field* field = curve.point_fields.find("level");
  if (field == nullptr) throw Error("the curve has no point field 'level' (exclusion.curve gives one)");
  auto wanted = [&](std::size_t i) {
    const int l = static_cast<int>(field->at(i));
    return opt.level < 0 ? l >= 1 : l == opt.level;
  };
  double discs = 0;
  for (std::size_t i = 0; i < curve.points.size(); ++i) discs += wanted(i);
  check_budget(discs * (opt.samples + 1), opt.budget, "the discs");
  Polyline out;
  std::vector<std::int32_t> levels;
  for (std::size_t i = 0; i < curve.points.size(); ++i) {
    if ((i & 1023) == 0) progress.step(static_cast<double>(i) / curve.points.size());
    if (!wanted(i)) continue;
    const int l = static_cast<int>(field->at(i));
    const double r = opt.radius * std::pow(opt.factor, l - 1);
    for (int k = 0; k <= opt.samples; ++k)
      out.points.push_back(curve.points[i] + r * polar(2 * 3.14159265358979323846 * (k % opt.samples) / opt.samples));
    out.close_path();
    levels.push_back(l);
  }
  out.cell_fields.set(int_field("level", std::move(levels)));
  if (!out.finite()) throw Error("the discs have non-finite points (a radius too large for the curve's coordinates)");
  return out;
}

}  // namespace selfsim::exclusion
