#include "kernels/develop/develop.h"

#include "kernels/develop/level_stack.h"
#include "kernels/geom/check.h"

namespace selfsim::develop {

void DevelopOptions::validate() const { check_range(smooth, 0, 12, "option 'smooth'"); }

Mesh develop_surface(std::span<const Polyline* const> levels, const DevelopOptions& opt, Progress& progress) {
  opt.validate();
  ProgressStage build(progress, 0, opt.smooth > 0 ? 0.1 : 1);
  Mesh m = control_mesh(levels, {opt.height}, build);
  if (opt.smooth == 0) return m;
  LoopOptions loop{opt.smooth, {}, opt.budget};
  if (!closed_levels(levels)) {
    // Points are numbered level by level: level 0's two ends first, the finest level's ends last.
    const auto first_end = static_cast<std::uint32_t>(levels.front()->points.size() - 1);
    const auto last_start = static_cast<std::uint32_t>(m.points.size() - levels.back()->points.size());
    loop.corners = {0, first_end, last_start, static_cast<std::uint32_t>(m.points.size() - 1)};
  }
  ProgressStage smooth(progress, 0.1, 1);
  return loop_subdivide(m, loop, smooth);
}

}  // namespace selfsim::develop
