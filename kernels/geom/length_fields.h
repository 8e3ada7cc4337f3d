// Point fields that are lengths in the curve's own units, so a similarity that scales the curve scales them
// too: `width` (a turtle's line widths, drawn by SVG and previews in the curve's units), `root_distance`
// (along a plant from its root) and `arclength` (along each path). Without this a plant laid out on a
// contact sheet (scaled to fit its cell) would keep trunks as wide as in its own frame. Cell fields are
// never lengths here (a group's cell `width` is a stroke width in pixels of the drawing).
#pragma once

#include "kernels/geom/field.h"

namespace selfsim {

// Multiplies those point fields (one component) by `factor` (a similarity's scale, positive); an int field
// of that name becomes a real one.
void scale_length_fields(Fields& point_fields, double factor);

}  // namespace selfsim
