// The growing exclusion curves of one run (seed 004): every curve as a chain of vertices, and the live
// segments of the curves and of the region's boundary in a grid, so that a split measures only the
// segments near it (with brute_force, every one). exclusion_curve.cpp drives it level by level or depth
// first; split_reach.h measures each obstacle.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "kernels/exclusion/exclusion_curve.h"
#include "kernels/exclusion/split_reach.h"
#include "kernels/geom/segment_grid.h"

namespace selfsim::exclusion {

inline constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();

struct Segment {
  Vec2 u, v;
  std::uint32_t from = none, to = none;  // the curve's vertices at u and v (none for the boundary's)
  bool alive = true;
  std::uint32_t seen = 0;  // the query that last visited it (a grid lists a segment in several cells)
};

class Curves {
 public:
  Curves(const Region& region, const Polyline& start, const CurveOptions& opt, double points);

  // Lists this moment's segments afresh, in a grid of the given cell size (dead segments dropped).
  void index(double cell);
  // Splits the segment that starts at vertex v with radius r; returns the new vertex.
  std::uint32_t split(std::uint32_t v, double r, int level, LevelReport& report);
  // Curve i's vertices in order from its first (a closed curve's first not repeated) and whether it is closed.
  std::vector<std::uint32_t> chain(std::size_t i) const;
  bool closed(std::size_t i) const { return closed_[i]; }
  std::size_t curves() const { return first_.size(); }
  double mean_length() const;
  Polyline result() const;

 private:
  // Numbers the vertices afresh in the order of their curves.
  void renumber();
  Reach reach(const SplitFrame& f, double r, std::uint32_t v);
  void limit(const SplitFrame& f, std::uint32_t id, std::uint32_t self, double r, Reach& limits);
  std::uint32_t add(Vec2 u, Vec2 v, std::uint32_t from = none, std::uint32_t to = none);
  // Whether vertex x's own terms are still to be measured in this query (a vertex ends two segments).
  bool first_visit(std::uint32_t x);

  const Region& region_;
  const CurveOptions& opt_;
  std::vector<Vec2> at_;
  std::vector<std::uint32_t> next_, prev_, out_;  // next and previous vertex along the curve, segment
                                                  // starting here (or none)
  std::vector<std::int32_t> level_;               // the level each vertex was made at
  std::vector<std::uint32_t> first_;              // each curve's first vertex
  std::vector<bool> closed_;
  std::vector<Segment> segments_;
  SegmentGrid grid_;
  std::uint32_t query_ = 0;
  std::vector<std::uint32_t> vertex_seen_;  // the query that last measured each vertex's terms
  double far_;                              // no point moves farther than this: the region's size
};

}  // namespace selfsim::exclusion
