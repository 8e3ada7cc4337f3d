// A polyline as a tube of triangles, for views that draw a curve's `width` (a plant's branch widths from
// '!'): a ring of `sides` points round each point of the line, perpendicular to it, the rings of consecutive
// points joined by two triangles per side. The rings' frames are carried along the line (parallel transport),
// so a tube does not twist where the line turns, and a straight line's rings all align. Open ends (no caps):
// a branch's end is smaller than a pixel at the radii views use.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace selfsim::io {

// Appends the rings of the line through `points` (radius radii[i] at points[i]) to `positions` (each ring
// point's x, y, z, ring after ring, `sides` a ring) and the triangles joining them to `triangles` (indices,
// counted from `first`, the index of the first ring point appended). Fewer than two points, or a line whose
// points all coincide: nothing. Returns the number of ring points appended.
std::size_t tube_rings(std::span<const std::array<double, 3>> points, std::span<const double> radii, int sides,
                       std::uint32_t first, std::vector<std::array<double, 3>>& positions,
                       std::vector<std::uint32_t>& triangles);

}  // namespace selfsim::io
