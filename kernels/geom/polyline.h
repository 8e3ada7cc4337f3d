// A curve made of one or more polylines ("paths") sharing one point array. Branches of an L-system and the
// several curves of a composition are separate paths of one Polyline.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "kernels/geom/bbox.h"
#include "kernels/geom/similarity.h"
#include "kernels/geom/vec2.h"

namespace selfsim {

struct Polyline {
  std::vector<Vec2> points;            // all paths' points, path after path
  std::vector<std::size_t> path_ends;  // path i is points[path_ends[i-1] (or 0) .. path_ends[i])
  int level = 0;                       // construction level, written as a point field

  // A polyline of a single path through `pts`.
  static Polyline single(std::vector<Vec2> pts, int level = 0);

  std::size_t paths() const { return path_ends.size(); }
  std::size_t path_begin(std::size_t i) const { return i == 0 ? 0 : path_ends[i - 1]; }
  std::span<const Vec2> path(std::size_t i) const {
    return {points.data() + path_begin(i), path_ends[i] - path_begin(i)};
  }
  // Number of line segments over all paths.
  std::size_t segments() const;
  // Total length of all paths.
  double length() const;
  BBox2 bbox() const { return bbox_of(points); }
  // True if every coordinate is finite.
  bool finite() const;
  // Ends the current path at the current end of `points` (no-op for an empty path).
  void close_path();
};

// c with every point mapped by t (paths and level kept).
Polyline transformed(const Polyline& c, const Similarity2& t);

}  // namespace selfsim
