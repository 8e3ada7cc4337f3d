// Segments of the plane in a uniform grid of square cells (seed 004's neighbour queries: no O(N²) scans).
// The cells cover given bounds densely; a segment or a query beyond them falls in the edge cells, so every
// answer stays right, only slower. Each segment is listed in every cell it passes through; a query visits
// the cells a box covers.
#pragma once

#include <cstdint>
#include <vector>

#include "kernels/geom/bbox.h"
#include "kernels/geom/vec2.h"

namespace selfsim {

class SegmentGrid {
 public:
  SegmentGrid() = default;  // no cells; insert and queries need a grid made with bounds
  // Cells of side `cell` (positive, finite) over `bounds` (non-empty, finite); larger cells when that would
  // make more than 2^22 of them.
  SegmentGrid(const BBox2& bounds, double cell);

  // Lists segment `id` from a to b in the cells it passes through.
  void insert(std::uint32_t id, Vec2 a, Vec2 b);

  // The ids of segments whose cells meet `box`, each once, in increasing order. A superset of the segments
  // that come within the box: callers measure the real distances.
  std::vector<std::uint32_t> near(const BBox2& box) const;
  // The same into `out` (cleared first), reusing its memory.
  void near(const BBox2& box, std::vector<std::uint32_t>& out) const;
  // Calls f(id) for each entry of the cells `box` meets: a segment in several of them comes several times
  // (the fastest query; callers that must see each once keep their own marks).
  template <class F>
  void visit(const BBox2& box, F&& f) const {
    if (cells_.empty() || box.empty()) return;
    const int i0 = column(box.min.x), i1 = column(box.max.x), j0 = row(box.min.y), j1 = row(box.max.y);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i)
        for (std::uint32_t id : cells_[static_cast<std::size_t>(j) * nx_ + i]) f(id);
  }

  double cell() const { return cell_; }
  // How many cells list at least one segment (box counting).
  std::size_t occupied() const;

 private:
  int column(double x) const;
  int row(double y) const;

  BBox2 bounds_;
  double cell_ = 0;
  int nx_ = 0, ny_ = 0;
  std::vector<std::vector<std::uint32_t>> cells_;
};

}  // namespace selfsim
