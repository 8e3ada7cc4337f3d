// A region of the plane for seed 004's curves: an outer simple polygon, optionally with holes (simple
// polygons inside it, apart from it and from each other). It answers whether a point is inside and how far
// a point or a segment is from its boundary; its edges are what an exclusion curve treats as one more curve
// that is never split.
#pragma once

#include <cstddef>
#include <vector>

#include "kernels/geom/bbox.h"
#include "kernels/geom/segment_grid.h"
#include "kernels/geom/vec2.h"

namespace selfsim {

class Region {
 public:
  // rings[0] is the outer boundary, the rest holes; each ring's points in order, its last edge back to its
  // first point (a repeated first point at the end is dropped). Throws Error naming the first problem: a ring
  // of fewer than 3 points, a non-finite point, a zero-length edge, a ring that crosses or touches itself
  // (naming the two edges), a hole outside the outer ring, rings that cross or touch each other.
  explicit Region(std::vector<std::vector<Vec2>> rings);

  // This region with every point p moved to scale·(p − centre), without checking its rings again (a
  // scale by a power of two keeps them as they were; callers work at a convenient size).
  Region moved(Vec2 centre, double scale) const;

  // True when p is inside the outer ring and outside every hole (a point on the boundary counts as inside).
  bool contains(Vec2 p) const;
  // Distance from p to the nearest boundary edge.
  double distance(Vec2 p) const;
  // Distance from segment a-b to the nearest boundary edge (zero if it crosses or touches the boundary).
  double distance(Vec2 a, Vec2 b) const;

  const std::vector<std::vector<Vec2>>& rings() const { return rings_; }
  std::size_t edges() const { return starts_.size(); }
  // Edge e runs from edge_start(e) to edge_end(e); edges are numbered ring after ring.
  Vec2 edge_start(std::size_t e) const { return starts_[e]; }
  Vec2 edge_end(std::size_t e) const { return ends_[e]; }
  BBox2 bbox() const { return box_; }

 private:
  Region() = default;
  // Rings, edges, box and grid, refusing only what they cannot be built from (too few points, non-finite,
  // zero-length edges, an overflowing extent).
  void build(std::vector<std::vector<Vec2>> rings);
  // The rings simple, apart, holes inside the outer ring and each enclosing some area.
  void check_rings() const;
  double distance_within(const BBox2& box, Vec2 a, Vec2 b) const;

  std::vector<std::vector<Vec2>> rings_;
  std::vector<Vec2> starts_, ends_;
  BBox2 box_;
  SegmentGrid grid_;
};

}  // namespace selfsim
