// How the vector formats (SVG, EPS) lay a curve out and draw each of its paths. A curve may carry its own
// style in cell fields (a group's members given `stroke`, `stroke_width` or `fill`): `color` (stroke, RGB in [0, 1]),
// `width` (stroke width in the drawing's unit) and `fill` (RGB in [0, 1], or negative for none). save()'s options, when
// given, override them; each option is one value or a palette, the member numbered k by the `curve` cell field taking
// entry (k − 1) mod size (a curve without that field is one member).
// A turtle's curve may also carry one-component point fields (module_turtle.h): `width` (its '!' line width)
// and `color` (its '\'' colour index). A segment takes its end point's: the width drawn as every picture draws
// it (drawn_width.h: relative to the drawing, the widest 2.4% of its diagonal across, the others in proportion),
// the stroke the index's class_colour (io/text/palette.h, the colours previews use). Both only where nothing else
// styles the path (an option or a cell field wins) and only for paths that are not filled (a fill needs whole paths).
#pragma once

#include <cstdint>
#include <string>

#include "kernels/geom/polyline.h"
#include "kernels/io/save.h"

namespace selfsim::io {

// The drawing's frame: the curve's bounding box with a 2% margin, mapped so its longer side is `size`
// drawing units (pixels, points, or the unit of a physical size).
struct DrawingFrame {
  Vec2 lo;          // the margin box's lower left corner, in curve units
  Vec2 extent;      // the margin box's size, in curve units
  double scale;     // drawing units per curve unit
  double diameter;  // the curve's own larger side (without the margin), in curve units
  double reach;     // the curve's largest absolute coordinate, in curve units
};

// The message for a drawing whose size or stroke width overflows.
inline const char* const drawing_overflow =
    "the curve's extent and the options give a non-finite drawing size or stroke width (scale the curve)";

// Throws Error when anything the file's header derives from the extent is not a finite number.
DrawingFrame drawing_frame(const Polyline& c, double size);

// Significant digits for coordinates: nine relative to the curve's own extent, so a curve far from the
// origin (a dragon moved to (1e8, 1e8)) keeps its detail; at most the 17 a double holds.
int coordinate_digits(const DrawingFrame& f);

struct PathStyle {
  std::string stroke;  // "#rrggbb" or a CSS name
  double width = 1;    // in the drawing's unit (pixels, or the unit of a physical size)
  std::string fill;    // "none", "#rrggbb" or a CSS name

  bool operator==(const PathStyle&) const = default;
};

class CurveStyles {
 public:
  // Throws Error naming the first path (or point) whose style fields are out of range. `units` is drawing
  // units (pixels, or the size's unit) per curve unit, for widths given in the curve's units.
  CurveStyles(const Polyline& c, const SaveOptions& opt, double units = 1);
  PathStyle at(std::size_t path) const;
  // Whether the segments of this path are styled one by one (point fields), and the style of the segment
  // ending at point `point` (an index into the curve's points) of a path whose own style is `path_style`.
  bool per_segment(const PathStyle& path_style) const;
  PathStyle segment(const PathStyle& path_style, std::size_t point) const;

 private:
  const SaveOptions& opt_;
  const Field *member_, *color_, *width_, *fill_;
  const Field *point_width_, *point_color_;  // used only where nothing else styles the paths
  bool stroke_given_, width_given_, fill_given_;
  double units_;
  double widest_ = 0, diagonal_ = 0;      // the largest |width| and the curve's diagonal, for drawn_radius
  mutable std::int64_t last_index_ = -1;  // the last colour index and its text: runs of one index are common
  mutable std::string last_colour_;
};

}  // namespace selfsim::io
