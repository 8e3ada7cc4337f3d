// The colours every picture of selfsim shares, so that a preview PNG, an SVG, a ParaView view and the studio's
// 3D view agree: a continuous ramp for numbers, and distinct colours for classes. No VTK here: the renderer,
// the SVG writer and the studio's page all read them.
#pragma once

#include <cstddef>

#include "kernels/io/text/colour.h"

namespace selfsim::io {

// A perceptually even blue-green-yellow ramp (after matplotlib's viridis) at t in [0, 1] (clamped).
Rgb ramp_colour(double t);

// The colour of the i-th class (0, 1, 2, ...): hues a golden angle apart from a blue, three lightness and
// saturation steps out of phase with them, so that neighbouring classes never look alike and 256 classes
// still separate. The same as a ParaView view's (paraview_view_body.py, category_colours).
Rgb class_colour(std::size_t i);

}  // namespace selfsim::io
