#include "kernels/develop/develop.h"

#include <cmath>

#include "kernels/develop/level_stack.h"
#include "kernels/develop/thicken.h"
#include "kernels/geom/check.h"

namespace selfsim::develop {

void DevelopOptions::validate() const {
  check_range(smooth, 0, 12, "option 'smooth'");
  check_between(thickness, 0, 1e6, "option 'thickness'");
  if (thickness_rate != 0) check_between(thickness_rate, 1e-6, 1, "option 'thickness_rate'");
}

Mesh develop_surface(std::span<const Polyline* const> levels, const DevelopOptions& opt, Progress& progress) {
  opt.validate();
  ProgressStage build(progress, 0, opt.smooth > 0 ? 0.1 : 1);
  Mesh m = control_mesh(levels, {opt.height}, build);
  if (opt.thickness > 0) {
    // Level l's thickness: thickness · rate^l, or thickness · (segment length of level l / of level 0).
    std::vector<double> per_level;
    const double first = levels.front()->length() / static_cast<double>(levels.front()->segments());
    for (std::size_t l = 0; l < levels.size(); ++l)
      per_level.push_back(opt.thickness_rate > 0 ? opt.thickness * std::pow(opt.thickness_rate, static_cast<double>(l))
                                                 : opt.thickness * levels[l]->length() /
                                                       static_cast<double>(levels[l]->segments()) / first);
    const Field* level = m.point_fields.find("level");
    std::vector<double> t(m.points.size());
    for (std::size_t i = 0; i < t.size(); ++i) t[i] = per_level[static_cast<std::size_t>(level->at(i))];
    m.point_fields.set(real_field("thickness", std::move(t)));
  }
  if (opt.smooth == 0) return opt.thickness > 0 ? thicken(m, progress) : m;
  LoopOptions loop{opt.smooth, {}, opt.budget};
  if (!closed_levels(levels)) {
    // Points are numbered level by level: level 0's two ends first, the finest level's ends last.
    const auto first_end = static_cast<std::uint32_t>(levels.front()->points.size() - 1);
    const auto last_start = static_cast<std::uint32_t>(m.points.size() - levels.back()->points.size());
    loop.corners = {0, first_end, last_start, static_cast<std::uint32_t>(m.points.size() - 1)};
  }
  ProgressStage smooth(progress, 0.1, opt.thickness > 0 ? 0.9 : 1);
  Mesh s = loop_subdivide(m, loop, smooth);
  if (opt.thickness == 0) return s;
  ProgressStage solid(progress, 0.9, 1);
  return thicken(s, solid);
}

}  // namespace selfsim::develop
