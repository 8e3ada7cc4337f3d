// The chains of Bowyer's program for one run of original_curve (original_rule.h): the region's rings
// (never split) and the curves as linked vertices, in the coordinates of the run, and the limits of one
// split measured by his brute force or through the grid (original_grid.h), which give the same bits.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "kernels/exclusion/original_grid.h"
#include "kernels/exclusion/original_split.h"
#include "kernels/geom/polyline.h"
#include "kernels/region/region.h"

namespace selfsim::exclusion::original {

inline constexpr std::uint32_t no_vertex = std::numeric_limits<std::uint32_t>::max();

class Chains {
 public:
  // The region's rings and the start's paths (a path ending at its first point is a closed curve), every
  // point multiplied by `scale`; room for `points` curve points.
  Chains(const Region& region, const Polyline& start, double scale, bool brute_force, double points);

  std::size_t curves() const { return first_.size(); }
  // Curve i's vertices in order from its first.
  std::vector<std::uint32_t> chain(std::size_t i) const;
  bool has_next(std::uint32_t v) const { return next_[v] != no_vertex; }
  // Lists every obstacle afresh for a level whose first radius is r (grid only).
  void begin_level(double r);
  // Splits the segment from vertex a with radius r, making a point of this level; returns its move t
  // (0: stuck). Throws Error if a side of the split was never stopped.
  double split(std::uint32_t a, double r, int level);
  // The curves, each point divided by the scale, start points exactly as given; fields `level`, `curve`.
  Polyline result(const Polyline& start, double scale) const;

 private:
  struct Walker;
  // Numbers the vertices afresh along their curves, so that neighbours along a curve are near in memory.
  void renumber();
  std::uint32_t add_segment(Vec2 p, Vec2 q);
  void list_vertex(std::uint32_t v);
  void limits_brute(const Frame& f, std::uint32_t a, std::uint32_t b, Limits& l) const;
  void limits_grid(const Frame& f, std::uint32_t a, std::uint32_t b, Limits& l) const;

  bool brute_force_;
  std::size_t boundary_;  // vertices 0 .. boundary_ - 1 are the region's rings'
  std::vector<Vec2> at_;
  std::vector<std::uint32_t> next_, out_;  // the next vertex along the chain; the segment record from here
  std::vector<std::int32_t> level_;        // -1 for the region's
  std::vector<std::uint32_t> first_;       // each curve's first vertex
  std::vector<bool> closed_;
  // Grid only. Segment records since the level began: ends, whether still a segment of the chains, and
  // the walk that last measured each (a segment is listed in several cells).
  std::vector<Vec2> from_, to_;
  std::vector<std::uint8_t> alive_;
  mutable std::vector<std::uint32_t> seen_;
  mutable std::uint32_t walks_ = 0;
  std::vector<std::uint32_t> outside_vertices_, outside_segments_;  // beyond the grid's bounds
  ObstacleGrid grid_;
  double size_ = 1;      // the grid's largest coordinate or extent, for rounding allowances
  double shortest_ = 0;  // no segment of this level is shorter (a split's halves are at least half as long)
};

}  // namespace selfsim::exclusion::original
