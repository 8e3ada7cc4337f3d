// Ids of 3D boxes (triangles' bounding boxes) in a uniform grid of cubic cells: the neighbour queries of the
// exclusion surface (seed 004 in 3D), so that a move measures only the triangles near it. The cells cover
// given bounds densely; a box beyond them falls in the edge cells, so answers stay right, only slower. An id
// is listed in every cell its box meets, and may be listed again when its box changes (the caller measures
// real distances, and keeps its own marks to see each id once).
#pragma once

#include <cstdint>
#include <vector>

#include "kernels/geom/bbox.h"

namespace selfsim {

class BoxGrid3 {
 public:
  BoxGrid3() = default;  // no cells
  // Cells of side `cell` (positive, finite) over `bounds` (non-empty, finite); larger cells when that would
  // make more than 2^21 of them.
  BoxGrid3(const BBox3& bounds, double cell);

  void insert(std::uint32_t id, const BBox3& box);

  // Calls f(id) for each entry of the cells `box` meets (an id in several of them comes several times).
  template <class F>
  void visit(const BBox3& box, F&& f) const {
    if (cells_.empty() || box.empty()) return;
    const Index lo = index(box.min), hi = index(box.max);
    for (int k = lo.k; k <= hi.k; ++k)
      for (int j = lo.j; j <= hi.j; ++j)
        for (int i = lo.i; i <= hi.i; ++i)
          for (std::uint32_t id : cells_[(static_cast<std::size_t>(k) * ny_ + j) * nx_ + i]) f(id);
  }

  double cell() const { return cell_; }

 private:
  struct Index {
    int i, j, k;
  };
  Index index(Vec3 p) const;

  BBox3 bounds_;
  double cell_ = 0;
  int nx_ = 0, ny_ = 0, nz_ = 0;
  std::vector<std::vector<std::uint32_t>> cells_;
};

}  // namespace selfsim
