#include "kernels/hoist/hoist.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>

#include "kernels/base/error.h"
#include "kernels/geom/all_finite.h"

namespace selfsim::hoist {

Polyline hoist_onto(Polyline q, const BaseCurve& p, Boundary boundary, Progress& progress) {
  constexpr std::size_t chunk = std::size_t{1} << 14;
  const std::size_t n = q.points.size();
  std::atomic<bool> stop{false};
  // Each chunk is one unit of work: workers check for a stop there; only this thread reports.
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, n, chunk),
      [&](const tbb::blocked_range<std::size_t>& r) {
        if (stop.load(std::memory_order_relaxed) || progress.cancelled()) {
          stop = true;
          return;
        }
        for (std::size_t i = r.begin(); i < r.end(); ++i) {
          const Vec2 z = q.points[i];
          const Frame f = p.at(z.x, boundary);
          q.points[i] = f.position + z.y * f.normal();
        }
      },
      tbb::simple_partitioner());
  if (stop) throw Cancelled();
  progress.fraction(1);
  if (!all_finite<Vec2>(q.points))
    throw Error("hoisting gave non-finite points (the path or the base curve is too large)");
  return q;
}

}  // namespace selfsim::hoist
