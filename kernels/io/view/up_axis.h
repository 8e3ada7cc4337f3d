// Which way is up in a picture of a 3D dataset. Plants stand along +y (the turtle starts heading +y) and so
// does anything without a clue, as in ABOP's figures; a dataset that says how it grew says its own up: a
// field named `level` (the step that made each point or face: a developing surface's stack, a growth) that
// follows one axis strongly makes that axis up, its positive direction up whichever way the level runs (a
// surface that develops downwards is drawn hanging, as it is). The previews' front and oblique views (preview_png.h)
// and the ParaView view stand on it; `selfsim preview --up x|y|z` overrides it. A print (.3mf, .stl, a checked
// mesh) stands on its build plate, +z up.
#pragma once

#include <string>

#include "kernels/io/dataset/dataset.h"
#include "kernels/io/format.h"

namespace selfsim::io {

// How strongly `level` must follow an axis for that axis to be up: the size of Pearson's correlation between
// the level and the coordinate (a cell's level with its centre's), at least this, and the largest of the three.
inline constexpr double up_correlation = 0.7;

// 0 (x), 1 (y) or 2 (z): the axis `level` follows (|correlation| at least up_correlation, the largest of
// the three), else 1. A point field `level` is used before a cell field.
int up_axis(const Dataset& d);
// The same for a dataset read from `file`: a print's up is +z, whatever it holds, as a slicer shows it on its
// build plate at z = 0: a .3mf or .stl file (the formats slicers read), or the print check's marked mesh
// (a `wall` field); else up_axis(d).
int up_axis(const Dataset& d, const std::string& file);
// The same for a value about to be saved (the run's ParaView view, paraview_view.h); a 2D curve: 1.
int up_axis(const ValueRef& v);

// 0, 1 or 2 for "x", "y" or "z"; -1 for anything else.
int axis_from_name(const std::string& name);

}  // namespace selfsim::io
