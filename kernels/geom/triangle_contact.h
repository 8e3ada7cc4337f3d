// The pair test of mesh_intersections.h: whether two triangles of a mesh meet (come within eps of each other)
// other than along the corners they share, and where. Triangles apart in the mesh (no shared point index)
// meet when the distance between them is at most eps: a crossing, a touch at a point, a coplanar overlap.
// Neighbours meet where they share by construction, and wrongly when they also meet elsewhere: sharing a
// corner, when a ray from it lies in both; sharing an edge, when they fold onto each other (their third
// corners on one side of it, within eps of one plane).
#pragma once

#include <array>
#include <optional>

#include "kernels/geom/mesh.h"
#include "kernels/geom/vec3.h"

namespace selfsim {

// A triangle's corners with what the tests reuse: its normal and whether it is flat.
struct ContactTriangle {
  std::array<Vec3, 3> v;
  Vec3 n;     // cross(v1 - v0, v2 - v0): twice the area, along the normal
  bool flat;  // height below 1e-12 of the longest edge: tested as its edges (a segment or a point)

  explicit ContactTriangle(const std::array<Vec3, 3>& corners) : v(corners), n(cross(v[1] - v[0], v[2] - v[0])) {
    const double longest =
        std::max({dot(v[1] - v[0], v[1] - v[0]), dot(v[2] - v[1], v[2] - v[1]), dot(v[0] - v[2], v[0] - v[2])});
    flat = dot(n, n) <= 1e-24 * longest * longest;
  }
  // Whether x, a point of the triangle's plane, lies in the triangle (edges included).
  bool contains(Vec3 x) const {
    return dot(cross(v[1] - v[0], x - v[0]), n) >= 0 && dot(cross(v[2] - v[1], x - v[1]), n) >= 0 &&
           dot(cross(v[0] - v[2], x - v[2]), n) >= 0;
  }
};

// Where triangles ia and ib (point indices; a and b their corners) meet wrongly, if they do: for triangles
// sharing no index, a point of both within eps; for neighbours, a shared corner or a point of the fold.
std::optional<Vec3> triangles_meet(const Triangle& ia, const Triangle& ib, const ContactTriangle& a,
                                   const ContactTriangle& b, double eps);

}  // namespace selfsim
