#include "kernels/exclusion/original_grid.h"

#include "kernels/base/error.h"

namespace selfsim::exclusion::original {

void ObstacleGrid::reset(const BBox2& bounds, double cell) {
  if (!(cell > 0 && std::isfinite(cell)) || bounds.empty() || !is_finite(bounds.min) || !is_finite(bounds.max))
    throw Error("an obstacle grid needs finite bounds and a positive cell size");
  bounds_ = bounds;
  cell_ = cell;
  const Vec2 size = bounds.size();
  constexpr double most = 4194304;  // 2^22 cells
  if ((size.x / cell_ + 1) * (size.y / cell_ + 1) > most) cell_ = std::max(size.x, size.y) / std::sqrt(most) * 1.01;
  // Counted as index() counts, so that every covered point falls in a cell.
  inverse_cell_ = 1 / cell_;
  nx_ = static_cast<int>(std::floor(size.x * inverse_cell_)) + 1;
  ny_ = static_cast<int>(std::floor(size.y * inverse_cell_)) + 1;
  // A few thousand roundings of the largest coordinate, and a sliver of a cell.
  pad_ = 1e-12 * std::max(largest_coordinate(bounds), std::max(size.x, size.y)) + 1e-9 * cell_;
  const std::size_t cells = static_cast<std::size_t>(nx_) * ny_;
  vertices_.clear(cells);
  segments_.clear(cells);
  directions_.assign(cells, 0);
}

template <class Entry>
void ObstacleGrid::Cells<Entry>::clear(std::size_t cells) {
  begin.assign(cells + 1, 0);
  items.clear();
  head.assign(cells, none_);
  next.clear();
  extra.clear();
}

template <class Entry>
void ObstacleGrid::Cells<Entry>::add(std::size_t cell, const Entry& e) {
  next.push_back(head[cell]);
  head[cell] = static_cast<std::uint32_t>(extra.size());
  extra.push_back(e);
}

template <class Entry>
void ObstacleGrid::Cells<Entry>::pack(const std::uint8_t* alive) {
  const std::size_t cells = head.size();
  auto keep = [&](const Entry& e) { return alive == nullptr || alive[e.id] != 0; };
  std::vector<std::uint32_t> count(cells + 1, 0);
  for (std::size_t cell = 0; cell < cells; ++cell) {
    for (std::uint32_t k = begin[cell]; k < begin[cell + 1]; ++k) count[cell + 1] += keep(items[k]);
    for (std::uint32_t k = head[cell]; k != none_; k = next[k]) count[cell + 1] += keep(extra[k]);
  }
  for (std::size_t cell = 0; cell < cells; ++cell) count[cell + 1] += count[cell];
  std::vector<Entry> packed(count[cells]);
  for (std::size_t cell = 0; cell < cells; ++cell) {
    std::uint32_t at = count[cell];
    for (std::uint32_t k = begin[cell]; k < begin[cell + 1]; ++k)
      if (keep(items[k])) packed[at++] = items[k];
    for (std::uint32_t k = head[cell]; k != none_; k = next[k])
      if (keep(extra[k])) packed[at++] = extra[k];
    head[cell] = none_;
  }
  begin = std::move(count);
  items = std::move(packed);
  next.clear();
  extra.clear();
}

ObstacleGrid::Bins ObstacleGrid::direction_bins(double angle, double half_width) {
  constexpr int count = 64;
  constexpr double bin = std::numbers::pi / count;
  if (!(half_width < std::numbers::pi / 2)) return ~Bins{0};
  // Angles from 0 to π, widths below π/2: shifted by a period, both ends are positive (truncation floors).
  const int lo = static_cast<int>((angle - half_width) * (1 / bin) + count) - count;
  const int hi = static_cast<int>((angle + half_width) * (1 / bin) + count) - count;
  if (hi - lo >= count - 1) return ~Bins{0};
  const Bins run = (Bins{2} << (hi - lo)) - 1;  // hi − lo + 1 bins
  const int shift = ((lo % count) + count) % count;
  return shift == 0 ? run : (run << shift) | (run >> (count - shift));
}

void ObstacleGrid::pack(const std::vector<std::uint8_t>& alive) {
  vertices_.pack(nullptr);
  segments_.pack(alive.data());
}

ObstacleGrid::Axes ObstacleGrid::axes(Vec2 m, Vec2 u) {
  if (std::abs(u.x) >= std::abs(u.y)) return {0, m.x, m.y, u.x, u.y, 1 / u.x};
  return {1, m.y, m.x, u.y, u.x, 1 / u.y};
}

void ObstacleGrid::add_vertex(std::uint32_t id, Vec2 p) {
  const int i = index(p.x, 0), j = index(p.y, 1);
  vertices_.add(static_cast<std::size_t>(j) * nx_ + i, {p, id});
}

void ObstacleGrid::add_segment(std::uint32_t id, Vec2 p, Vec2 q) {
  const Vec2 d = q - p;
  if (d.x == 0 && d.y == 0) {
    // A point: the cells within pad of it.
    for (int j = std::max(index(p.y - pad_, 1), 0); j <= std::min(index(p.y + pad_, 1), ny_ - 1); ++j)
      for (int i = std::max(index(p.x - pad_, 0), 0); i <= std::min(index(p.x + pad_, 0), nx_ - 1); ++i) {
        const std::size_t cell = static_cast<std::size_t>(j) * nx_ + i;
        segments_.add(cell, {p, q, id});
        directions_[cell] = ~Bins{0};
      }
    return;
  }
  const Bins bin = direction_bins(direction(d), 0);
  cover(axes(p, d), 0, 1, [&](std::size_t cell) {
    segments_.add(cell, {p, q, id});
    directions_[cell] |= bin;
  });
}

}  // namespace selfsim::exclusion::original
