// A mesh moved, turned and resized: Mesh:transform{ scale, rotate, axis, translate } and solid.orient.
// Scale first (about the origin, per axis; a negative factor mirrors), then the rotation about the origin,
// then the translation. What rides along with the points follows them: a mirror (an odd number of negative
// factors) reverses every triangle so the solid still faces outwards; point and face fields named `normal`
// or `normals` (3 components, any case: VTK's `Normals`) are directions normal to the surface, mapped by the
// inverse transpose and kept at their length (unit normals stay unit); length fields (length_fields.h:
// `thickness`, `width` and the others) scale by a uniform factor and are dropped under a
// non-uniform one, which no single factor describes; fields named `overhang` (any case: the print check's
// degrees below horizontal, relative to +z) are kept only by a map that keeps every face's tilt (a turn about
// z, a uniform scale, a mirror across a vertical plane, any translation) and dropped under any other.
#pragma once

#include <array>

#include "kernels/base/progress.h"
#include "kernels/geom/mesh.h"
#include "kernels/geom/vec3.h"

namespace selfsim {

// p -> M p + t, M any invertible matrix (row by row).
struct Affine3 {
  std::array<Vec3, 3> rows{Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
  Vec3 t{};

  Vec3 linear(Vec3 p) const { return {dot(rows[0], p), dot(rows[1], p), dot(rows[2], p)}; }
  Vec3 operator()(Vec3 p) const { return linear(p) + t; }
  double determinant() const { return dot(rows[0], cross(rows[1], rows[2])); }
};

struct MeshTransform {
  Vec3 scale{1, 1, 1};  // per axis, about the origin; negative mirrors; never zero
  double degrees = 0;   // counterclockwise seen from where `axis` points (right-hand rule)
  Vec3 axis{0, 0, 1};   // any non-zero length
  Vec3 translate{};

  // Throws Error naming the option: a zero or non-finite scale, a zero axis, a non-finite number.
  void validate() const;
  // The map: translate after rotate after scale.
  Affine3 map() const;
};

// The rotation by `degrees` about the unit vector `axis` (Rodrigues' formula).
Affine3 rotation(Vec3 axis, double degrees);

// m with every point mapped by a (invertible), triangles and fields following as above. Throws Error if a
// point overflows. Looks for a stop every 2^16 points.
Mesh transformed(const Mesh& m, const Affine3& a, Progress& progress = no_progress());

}  // namespace selfsim
