// Axis-aligned bounding box of 2D points.
#pragma once

#include <algorithm>
#include <limits>
#include <span>

#include "kernels/geom/vec2.h"

namespace selfsim {

struct BBox2 {
  Vec2 min{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  Vec2 max{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};

  bool empty() const { return min.x > max.x; }
  void add(Vec2 p) {
    min = {std::min(min.x, p.x), std::min(min.y, p.y)};
    max = {std::max(max.x, p.x), std::max(max.y, p.y)};
  }
  Vec2 size() const { return empty() ? Vec2{} : max - min; }
};

inline BBox2 bbox_of(std::span<const Vec2> points) {
  BBox2 b;
  for (Vec2 p : points) b.add(p);
  return b;
}

}  // namespace selfsim
