// Triangles of the even-odd region of closed 2D curves (what an SVG fill with fill-rule="evenodd" paints):
// an outline, holes inside it, islands inside the holes, and so on, and several such shapes side by side.
// What reliefs (kernels/print/relief.h) cap and what a base plate's top face is cut into.
//
// The method is the textbook one for polygons with holes, O(n log n) in the points: a sweep in
// lexicographic (y, then x) order cuts the region into y-monotone pieces with diagonals (each vertex is a
// start, split, end, merge or regular vertex; a balanced tree holds the edges that cross the sweep line, left
// to right, each with its "helper"), then each piece is triangulated in linear time by the stack method.
// The same sweep finds how deeply each path is nested (the edge just left of its lowest point says whether
// that point is inside), which orients every path with the region on its left: outlines counter-clockwise,
// holes clockwise, islands counter-clockwise... Orientation tests are exact (a floating-point filter with an
// exact fallback), so collinear runs and equal y-coordinates (staircases, combs) come out right.
// Points on one line only to a rounding (a Koch snowflake's sides) are a hair off it exactly; a triangle of
// three of them (a sliver a rounding high, which would make a relief's cap touch its walls) is flipped away
// with its neighbour wherever the region allows.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "kernels/base/progress.h"
#include "kernels/geom/polyline.h"
#include "kernels/geom/vec2.h"

namespace selfsim {

struct RegionTriangles {
  // The vertices used: every path's points in order, without its closing repeat of the first point and
  // without a point equal to the one before it. #vertices entries each below.
  std::vector<Vec2> points;
  std::vector<std::uint32_t> source;         // index of each vertex in the input's points
  std::vector<std::uint32_t> path_of_point;  // index of each vertex's path in the input (from 0)
  // The vertex after each one along its path, with the region on the left of every edge point → next:
  // the region's boundary, oriented (outlines counter-clockwise, holes clockwise).
  std::vector<std::uint32_t> next;
  // Counter-clockwise triangles of vertex indices covering the region once: #vertices + 2·#holes − 2 for
  // one outline with its holes, summed over the outlines (islands count as outlines).
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

// Triangulates the even-odd region of c's paths. Every path must be closed (its last point at its first to
// a billionth of its size: closed_path in polyline.h) with at least 3 distinct points, finite, and enclose
// an area; no path may cross or touch itself or another (checked over a uniform grid of the segments).
// Throws Error, one line beginning with `what` ("a relief needs closed curves: path 2 is open (...)"),
// naming the path and point counted from 1 and its coordinates. Reports progress and looks for a stop
// every 65,536 events.
RegionTriangles region_triangles(const Polyline& c, Progress& progress = no_progress(),
                                 std::string_view what = "a filled region");

}  // namespace selfsim
