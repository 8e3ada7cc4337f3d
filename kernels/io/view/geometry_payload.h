// A dataset as the studio's 3D view draws it (scripts/studio.html, with three.js): binary arrays a browser
// takes as they are (typed arrays over the bytes, no number parsing), coloured here with the preview's
// chooser and palette (natural_field.h, palette.h), so the view and the PNG agree.
//
// The bytes, little-endian, every array starting at a multiple of 4:
//   "SSG1", uint32 H, H bytes of JSON header (padded with spaces to a multiple of 4),
//   float32 positions[3 V] (relative to the header's origin: float32 keeps a far-off part's detail),
//   uint32 indices[3 T + 2 S] (T triangles, then S line segments, into the V vertices),
//   uint8 colours[3 V] (RGB per vertex), padded with zeros to a multiple of 4.
// The header: {"vertices": V, "triangles": T, "segments": S, "origin": [x, y, z], "bounds": [xmin, xmax,
// ymin, ymax, zmin, zmax], "legend": colouring_json(...)}. Neither triangles nor segments: draw the points.
//
// A field on cells colours each cell whole: a vertex shared by cells of different colours is sent once per
// colour (a copy of it per colour, not per cell, so a surface of few classes stays about as small as it is).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "kernels/base/progress.h"
#include "kernels/io/dataset/dataset.h"
#include "kernels/io/view/natural_field.h"

namespace selfsim::io {

// A curve's own colours: a cell field `color` of three components (red, green, blue in [0, 1]: an SVG's
// strokes read back), one per cell, in a dataset of lines alone. The preview draws them as they are when no
// field is asked for, and so does the view (with no colouring field).
bool has_own_colours(const Dataset& d);

// The legend the page draws, as JSON: {"field": NAME or "", "own": B (the cells' own colours),
// "on": "points" or "cells", "categorical": B, "min": A, "max": B, "ramp": [9 colours "#rrggbb" from min to
// max], "classes": [values], "colours": [one "#rrggbb" per class]} (classes and colours empty for a
// continuous field).
std::string colouring_json(const Colouring& c, bool own = false);

// The colour of a value under c (no field: the preview's one solid colour; a value not finite or no class
// of c: grey), as 0-255 RGB.
std::array<std::uint8_t, 3> value_colour(const Colouring& c, double v);

// A curve's widths drawn as every picture draws them (drawn_width.h): a point field `width` makes each polyline
// a tube, relative to `diagonal` (the drawing's, over every step of a series) and `max_width` (the largest
// |width| over every step). diagonal 0: lines.
struct TubeWidths {
  double diagonal = 0, max_width = 0;
};
inline constexpr int tube_sides = 8;
// More segments than this and a curve is drawn as lines after all: a browser draws a million triangles in
// about a second where WebGL runs on the CPU, and 16 triangles a segment would pass that.
inline constexpr std::size_t max_tube_segments = 50000;

// The line segments of d's polylines.
std::size_t line_segments(const Dataset& d);

// Whether d is drawn as tubes with these widths: a dataset of lines alone, with a one-component point field
// `width`, of at most max_tube_segments segments.
bool drawn_as_tubes(const Dataset& d, const TubeWidths& widths);

// The payload bytes of d coloured by c (a field d lacks, or holds with a count that does not match, draws in
// the solid colour; no field, by its own colours when it has them), its polylines as tubes when
// drawn_as_tubes(d, widths). Polygons are split into triangles (a fan),
// polylines into segments. Throws Error when a point is not finite, or when the payload would pass
// max_bytes (naming its size and the limit); Cancelled when progress says stop.
std::string geometry_payload(const Dataset& d, const Colouring& c, std::uint64_t max_bytes,
                             const TubeWidths& widths = {}, Progress& progress = no_progress());

}  // namespace selfsim::io
