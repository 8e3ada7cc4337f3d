// Similarity of the plane on complex numbers (seed 003 §1): T(z) = a·z + b, orientation-preserving, or
// T(z) = a·conj(z) + b when mirrored (seed 000's reflected copies).
#pragma once

#include "kernels/geom/vec2.h"

namespace selfsim {

struct Similarity2 {
  Vec2 a{1, 0}, b{0, 0};
  bool mirrored = false;

  Vec2 operator()(Vec2 z) const { return a * (mirrored ? conj(z) : z) + b; }

  // this ∘ inner: apply inner first.
  Similarity2 after(const Similarity2& inner) const {
    return {a * (mirrored ? conj(inner.a) : inner.a), (*this)(inner.b), mirrored != inner.mirrored};
  }

  // The similarity taking 0 to p and 1 to q (p != q).
  static Similarity2 from_segment(Vec2 p, Vec2 q) { return {q - p, p}; }
  // The similarity taking p to 0 and q to 1 (p != q): the inverse of from_segment.
  static Similarity2 to_unit(Vec2 p, Vec2 q) {
    const Vec2 a = Vec2{1, 0} / (q - p);
    return {a, -(a * p)};
  }
};

}  // namespace selfsim
