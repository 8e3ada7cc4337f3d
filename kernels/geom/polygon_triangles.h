// Triangles of one polygon face as a mesh file gives it (OBJ `f`, PLY faces, VTK polygons): corners in
// order, in 3D, planar or nearly so. A convex polygon is fanned from its first corner, as before; any
// other is cut into ears in the plane its corners best span (Newell's normal), so a concave polygon (an L,
// a star) gives triangles inside it that cover it once, never a fan reaching outside. Ear cutting is
// quadratic in the corners: polygons of more than max_concave_corners corners that are not convex are
// refused rather than left to run for minutes.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "kernels/geom/vec3.h"

namespace selfsim {

inline constexpr std::size_t max_concave_corners = 4096;

// Appends n - 2 triangles (indices into `corners`, in the polygon's own orientation) to `out`. Throws Error
// for a polygon that is not convex and crosses or touches itself (in its plane), or is too large to cut. A
// polygon with no area in any direction is fanned as it is.
void polygon_triangles(std::span<const Vec3> corners, std::vector<std::array<std::size_t, 3>>& out);

}  // namespace selfsim
