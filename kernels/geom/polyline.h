// A curve made of one or more polylines ("paths") sharing one point array, in 2D (Polyline, 16 bytes a
// point) or 3D (Polyline3). Branches of an L-system and the several curves of a composition are separate
// paths of one value. Point fields have one tuple per point, cell fields one per path (a path is one VTK
// polyline cell).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "kernels/geom/bbox.h"
#include "kernels/geom/field.h"
#include "kernels/geom/point_array.h"
#include "kernels/geom/similarity.h"
#include "kernels/geom/vec2.h"
#include "kernels/geom/vec3.h"

namespace selfsim {

template <class V>
struct PolylineT {
  using Point = V;

  PointArray<V> points;                // all paths' points, path after path
  std::vector<std::size_t> path_ends;  // path i is points[path_ends[i-1] (or 0) .. path_ends[i])
  Fields point_fields;                 // one tuple per point (or uniform)
  Fields cell_fields;                  // one tuple per path (or uniform)

  // A polyline of a single path through `pts`.
  static PolylineT single(const std::vector<V>& pts);

  std::size_t paths() const { return path_ends.size(); }
  std::size_t path_begin(std::size_t i) const { return i == 0 ? 0 : path_ends[i - 1]; }
  std::span<const V> path(std::size_t i) const { return {points.data() + path_begin(i), path_ends[i] - path_begin(i)}; }
  // Number of line segments over all paths.
  std::size_t segments() const;
  // Total length of all paths.
  double length() const;
  BBox<V> bbox() const { return bbox_of<V>(points); }
  // True if every coordinate is finite.
  bool finite() const;
  // True when the paths are well formed: ends increasing, each path non-empty, the last at points.size().
  bool paths_consistent() const;
  // Ends the current path at the current end of `points` (no-op for an empty path).
  void close_path();
  // Bytes of C++ memory the value holds (points, paths and fields).
  std::size_t bytes() const;
};

using Polyline = PolylineT<Vec2>;
using Polyline3 = PolylineT<Vec3>;
extern template struct PolylineT<Vec2>;
extern template struct PolylineT<Vec3>;

// c with every point mapped by t (paths and fields kept; length fields scaled with it: length_fields.h).
Polyline transformed(const Polyline& c, const Similarity2& t);

// True when a path of at least three points ends where it starts, to a billionth of its size: kernels that
// close a curve by walking (a turtle's loop, a substitution over a polygon) arrive back a rounding error
// away (the Koch snowflake's level 1 ends 3e-16 from its start). Develop's stacks and the SVG and EPS
// writers' Z / closepath use this one rule.
bool closed_path(std::span<const Vec2> path);

}  // namespace selfsim
