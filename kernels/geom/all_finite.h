// Whether every coordinate of many points is finite, fast enough to run over a whole vertex array: no early
// exit and no branch per coordinate (x - x is 0 for a finite x and NaN otherwise).
#pragma once

#include <span>

#include "kernels/geom/vec2.h"
#include "kernels/geom/vec3.h"

namespace selfsim {

inline bool finite_bits(Vec2 p) { return (p.x - p.x == 0) & (p.y - p.y == 0); }
inline bool finite_bits(Vec3 p) { return (p.x - p.x == 0) & (p.y - p.y == 0) & (p.z - p.z == 0); }

template <class V>
bool all_finite(std::span<const V> points) {
  bool ok = true;
  for (const V& p : points) ok &= finite_bits(p);
  return ok;
}

}  // namespace selfsim
