#include "kernels/geom/segment_grid.h"

#include <algorithm>
#include <cmath>

#include "kernels/geom/error.h"

namespace selfsim {

SegmentGrid::SegmentGrid(double cell) : cell_(cell) {
  if (!(cell > 0 && std::isfinite(cell))) throw Error("a segment grid needs a positive cell size");
}

std::int64_t SegmentGrid::index(double x) const {
  // Clamped so that far coordinates land in an edge cell instead of overflowing the key.
  return static_cast<std::int64_t>(std::clamp(std::floor(x / cell_), -1e9, 1e9));
}

std::uint64_t SegmentGrid::key(std::int64_t i, std::int64_t j) {
  return static_cast<std::uint64_t>(i + (1LL << 31)) << 32 | static_cast<std::uint64_t>(j + (1LL << 31));
}

void SegmentGrid::insert(std::uint32_t id, Vec2 a, Vec2 b) {
  const std::int64_t i0 = index(std::min(a.x, b.x)), i1 = index(std::max(a.x, b.x));
  const std::int64_t j0 = index(std::min(a.y, b.y)), j1 = index(std::max(a.y, b.y));
  // A segment far longer than the cells would fill millions of them: the caller chose the cell wrongly.
  if (static_cast<double>(i1 - i0 + 1) * static_cast<double>(j1 - j0 + 1) > 16777216.0)
    throw Error("a segment covers more than 2^24 cells of the grid: the cells are too small for it");
  for (std::int64_t i = i0; i <= i1; ++i)
    for (std::int64_t j = j0; j <= j1; ++j) cells_[key(i, j)].push_back(id);
}

std::vector<std::uint32_t> SegmentGrid::near(const BBox2& box) const {
  std::vector<std::uint32_t> out;
  if (box.empty()) return out;
  const std::int64_t i0 = index(box.min.x), i1 = index(box.max.x), j0 = index(box.min.y), j1 = index(box.max.y);
  for (std::int64_t i = i0; i <= i1; ++i)
    for (std::int64_t j = j0; j <= j1; ++j)
      if (const auto c = cells_.find(key(i, j)); c != cells_.end())
        out.insert(out.end(), c->second.begin(), c->second.end());
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace selfsim
