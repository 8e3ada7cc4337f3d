// SVG's transform attribute (SVG 1.1 §7.6): a 2x3 affine matrix, the transform list grammar, and applying
// it to points. The reader composes each element's matrix with its ancestors' (svg_element.h).
#pragma once

#include <string_view>

#include "kernels/geom/vec2.h"

namespace selfsim::io {

// x' = a x + c y + e, y' = b x + d y + f: SVG's matrix(a b c d e f).
struct Affine2 {
  double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;

  Vec2 apply(Vec2 p) const { return {a * p.x + c * p.y + e, b * p.x + d * p.y + f}; }
  // This map after `inner` (inner applies first).
  Affine2 after(const Affine2& inner) const {
    return {a * inner.a + c * inner.b, b * inner.a + d * inner.b,     a * inner.c + c * inner.d,
            b * inner.c + d * inner.d, a * inner.e + c * inner.f + e, b * inner.e + d * inner.f + f};
  }
  bool finite() const;
};

// The matrix of a transform attribute's value: matrix(a b c d e f), translate(x [y]), scale(x [y]),
// rotate(degrees [cx cy]), skewX(degrees), skewY(degrees), numbers separated by commas and/or white space
// (or nothing, where the grammar allows: "translate(1-2)"), the transforms of a list applied right to left
// ("translate(10) scale(2)" scales first). Empty text is the identity. Throws Error, one line, naming the
// attribute and what was expected, for malformed text or a matrix that overflows.
Affine2 parse_svg_transform(std::string_view text);

}  // namespace selfsim::io
