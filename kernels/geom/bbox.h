// Axis-aligned bounding box of 2D or 3D points.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "kernels/geom/vec2.h"
#include "kernels/geom/vec3.h"

namespace selfsim {

template <class V>
struct BBox {
  V min = V::all(std::numeric_limits<double>::infinity());
  V max = V::all(-std::numeric_limits<double>::infinity());

  bool empty() const { return min.x > max.x; }
  void add(V p) {
    min = min_each(min, p);
    max = max_each(max, p);
  }
  void add(const BBox& b) {
    if (b.empty()) return;
    add(b.min);
    add(b.max);
  }
  // Extent along each axis; zero for an empty box.
  V size() const { return empty() ? V{} : max - min; }
};

using BBox2 = BBox<Vec2>;
using BBox3 = BBox<Vec3>;

// How far from the origin a 2D box reaches along either axis: its largest absolute coordinate.
inline double largest_coordinate(const BBox2& b) {
  return std::max(std::max(std::abs(b.min.x), std::abs(b.min.y)), std::max(std::abs(b.max.x), std::abs(b.max.y)));
}

template <class V>
BBox<V> bbox_of(std::span<const V> points) {
  BBox<V> b;
  for (V p : points) b.add(p);
  return b;
}

}  // namespace selfsim
