// A triangle mesh: Vec3 points, triangles as point indices (counter-clockwise seen from outside: the
// right-hand rule gives the outward normal), and named point and face fields. What develop, exclusion
// surfaces, mesh{} and load() make, and what the mesh formats write.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "kernels/geom/bbox.h"
#include "kernels/geom/field.h"
#include "kernels/geom/vec3.h"

namespace selfsim {

using Triangle = std::array<std::uint32_t, 3>;

// Point indices are 32-bit: a mesh has at most this many points (about 4.3 billion, far past any budget).
inline constexpr double max_mesh_points = 4294967295.0;

struct Mesh {
  std::vector<Vec3> points;
  std::vector<Triangle> triangles;
  Fields point_fields;  // one tuple per point (or uniform)
  Fields face_fields;   // one tuple per triangle (or uniform)

  std::size_t faces() const { return triangles.size(); }
  BBox3 bbox() const { return bbox_of<Vec3>(points); }
  // True if every coordinate is finite.
  bool finite() const;
  // Bytes of C++ memory the value holds.
  std::size_t bytes() const;
  // Throws Error naming the first triangle that uses a point index out of range or one point twice, or a
  // non-finite point, or a field of the wrong size.
  void validate() const;
};

// Outward normal of triangle t times twice its area (zero for a degenerate triangle).
Vec3 area_normal(const Mesh& m, const Triangle& t);

// The box over the points the triangles use: what the solid occupies. Points no triangle uses (left by a
// filter, or a stray point in a loaded file) do not count, unlike Mesh::bbox(). Empty for a mesh without
// triangles.
BBox3 corner_bbox(const Mesh& m);

// The sum of the triangles' areas.
double surface_area(const Mesh& m);

// The volume a closed mesh encloses, positive when its triangles face outwards. Measured from the centre of
// its bounding box: from the origin, a shape far away (1e6) or small beside its distance (2e-6 at 1) sums
// terms that cancel to rounding noise and can come out with the wrong sign.
double enclosed_volume(const Mesh& m);
// Six times the signed volume of the tetrahedron from o to triangle t: enclosed_volume's term, for a part's.
double volume_term(const Mesh& m, const Triangle& t, Vec3 o);

}  // namespace selfsim
