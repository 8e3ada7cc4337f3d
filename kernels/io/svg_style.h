// The SVG style of each path of a curve. A curve may carry its own style in cell fields (a group's
// members given `stroke`, `stroke_width` or `fill`): `color` (stroke, RGB in [0, 1]), `width` (stroke width in
// the drawing's unit) and `fill` (RGB in [0, 1], or negative for none). save()'s options, when given,
// override them; each option is one value or a palette, the member numbered k by the `curve` cell field
// taking entry (k − 1) mod size (a curve without that field is one member).
#pragma once

#include <string>

#include "kernels/geom/polyline.h"
#include "kernels/io/save.h"

namespace selfsim::io {

struct PathStyle {
  std::string stroke;  // "#rrggbb" or a CSS name
  double width = 1;    // in the drawing's unit (pixels, or the unit of a physical size)
  std::string fill;    // "none", "#rrggbb" or a CSS name

  bool operator==(const PathStyle&) const = default;
};

class SvgStyles {
 public:
  // Throws Error naming the first path whose style fields are out of range.
  SvgStyles(const Polyline& c, const SaveOptions& opt);
  PathStyle at(std::size_t path) const;

 private:
  const SaveOptions& opt_;
  const Field *member_, *color_, *width_, *fill_;
  bool stroke_given_, width_given_, fill_given_;
};

}  // namespace selfsim::io
