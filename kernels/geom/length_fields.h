// Fields that are lengths in the value's own units, so a similarity that scales the value scales them too:
// `width` (a turtle's line widths, drawn by SVG and previews in the curve's units), `root_distance` (along a
// plant from its root), `arclength` (along each path), and a solid's `thickness`, `radius` (a tube's),
// `wall`, `gap` and `clearance` (mm, the print check's and an exclusion surface's). Without this a plant laid
// out on a contact sheet (scaled to fit its cell) would keep trunks as wide as in its own frame. A curve's
// cell fields are never lengths (a group's cell `width` is a stroke width in pixels of the drawing); a
// mesh's face fields can be (`wall`, `clearance`).
#pragma once

#include "kernels/geom/field.h"

namespace selfsim {

// Multiplies those fields (one component) by `factor` (a similarity's scale, positive); an int field of that
// name becomes a real one. A factor of 0 (a scale that differs between axes, which no one factor describes)
// drops them.
void scale_length_fields(Fields& fields, double factor);

}  // namespace selfsim
