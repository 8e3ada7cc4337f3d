#include "kernels/geom/segment_grid.h"

#include <algorithm>
#include <cmath>

#include "kernels/base/error.h"

namespace selfsim {

SegmentGrid::SegmentGrid(const BBox2& bounds, double cell) : bounds_(bounds), cell_(cell) {
  if (!(cell > 0 && std::isfinite(cell))) throw Error("a segment grid needs a positive cell size");
  if (bounds.empty() || !is_finite(bounds.min) || !is_finite(bounds.max))
    throw Error("a segment grid needs finite bounds");
  const Vec2 size = bounds.size();
  constexpr double most = 4194304;  // 2^22 cells
  if ((size.x / cell_ + 1) * (size.y / cell_ + 1) > most) cell_ = std::max(size.x, size.y) / std::sqrt(most) * 1.01;
  nx_ = static_cast<int>(size.x / cell_) + 1;
  ny_ = static_cast<int>(size.y / cell_) + 1;
  cells_.resize(static_cast<std::size_t>(nx_) * ny_);
}

int SegmentGrid::column(double x) const {
  return static_cast<int>(std::clamp(std::floor((x - bounds_.min.x) / cell_), 0.0, nx_ - 1.0));
}

int SegmentGrid::row(double y) const {
  return static_cast<int>(std::clamp(std::floor((y - bounds_.min.y) / cell_), 0.0, ny_ - 1.0));
}

void SegmentGrid::insert(std::uint32_t id, Vec2 a, Vec2 b) {
  if (cells_.empty()) throw Error("a segment grid without cells cannot list segments");
  if (a.x > b.x) std::swap(a, b);
  const int i0 = column(a.x), i1 = column(b.x);
  // Column by column, the rows between the segment's lowest and highest y within that column (the edge
  // columns reach to infinity), widened by far more than a rounding of x or y, so that a cell only grazed
  // is listed too.
  const double slope = b.x > a.x ? (b.y - a.y) / (b.x - a.x) : 0;
  const double pad = 1e-9 * cell_ * (1 + std::abs(slope));
  for (int i = i0; i <= i1; ++i) {
    const double x0 = i == i0 ? a.x : bounds_.min.x + i * cell_, x1 = i == i1 ? b.x : bounds_.min.x + (i + 1) * cell_;
    const double y0 = i == i0 ? a.y : a.y + slope * (x0 - a.x), y1 = i == i1 ? b.y : a.y + slope * (x1 - a.x);
    const int lo = row(std::min(y0, y1) - pad), hi = row(std::max(y0, y1) + pad);
    for (int j = lo; j <= hi; ++j) cells_[static_cast<std::size_t>(j) * nx_ + i].push_back(id);
  }
}

std::size_t SegmentGrid::occupied() const {
  return static_cast<std::size_t>(
      std::count_if(cells_.begin(), cells_.end(), [](const std::vector<std::uint32_t>& c) { return !c.empty(); }));
}

std::vector<std::uint32_t> SegmentGrid::near(const BBox2& box) const {
  std::vector<std::uint32_t> out;
  near(box, out);
  return out;
}

void SegmentGrid::near(const BBox2& box, std::vector<std::uint32_t>& out) const {
  out.clear();
  visit(box, [&](std::uint32_t id) { out.push_back(id); });
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

}  // namespace selfsim
