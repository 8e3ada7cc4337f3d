// Segments of the plane in a uniform grid of square cells (seed 004's neighbour queries: no O(N²) scans).
// Each segment is listed in every cell its bounding box covers; a query visits the cells a box covers and
// reports each segment once. Cells are keyed in a hash map, so an unbounded plane costs memory only where
// segments are.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "kernels/geom/bbox.h"
#include "kernels/geom/vec2.h"

namespace selfsim {

class SegmentGrid {
 public:
  // `cell`: the cells' side, positive and finite; about the length of a typical segment or query.
  explicit SegmentGrid(double cell);

  // Lists segment `id` from a to b. Throws Error if it would cover more than 2^24 cells.
  void insert(std::uint32_t id, Vec2 a, Vec2 b);

  // The ids of segments whose cells meet `box`, each once, in increasing order. A superset of the segments
  // that come within the box: callers measure the real distances.
  std::vector<std::uint32_t> near(const BBox2& box) const;

  double cell() const { return cell_; }

 private:
  std::int64_t index(double x) const;
  static std::uint64_t key(std::int64_t i, std::int64_t j);

  double cell_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
};

}  // namespace selfsim
