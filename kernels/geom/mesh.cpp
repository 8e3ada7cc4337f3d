#include "kernels/geom/mesh.h"

#include <string>

#include "kernels/base/error.h"
#include "kernels/geom/all_finite.h"

namespace selfsim {

bool Mesh::finite() const { return all_finite<Vec3>(points); }

std::size_t Mesh::bytes() const {
  return points.capacity() * sizeof(Vec3) + triangles.capacity() * sizeof(Triangle) + point_fields.bytes() +
         face_fields.bytes();
}

void Mesh::validate() const {
  if (static_cast<double>(points.size()) > max_mesh_points)
    throw Error("a mesh has at most 4294967295 points, got " + std::to_string(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!is_finite(points[i])) throw Error("point " + std::to_string(i + 1) + " has non-finite coordinates");
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    const Triangle& t = triangles[f];
    for (std::uint32_t v : t)
      if (v >= points.size())
        throw Error("triangle " + std::to_string(f + 1) + " uses point " + std::to_string(std::size_t{v} + 1) +
                    ", but there are " + std::to_string(points.size()) + " points");
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
      throw Error("triangle " + std::to_string(f + 1) + " uses one point twice");
  }
  point_fields.check(points.size(), "point");
  face_fields.check(triangles.size(), "face");
}

Vec3 area_normal(const Mesh& m, const Triangle& t) {
  const Vec3 a = m.points[t[0]], b = m.points[t[1]], c = m.points[t[2]];
  return cross(b - a, c - a);
}

BBox3 corner_bbox(const Mesh& m) {
  BBox3 b;
  for (const Triangle& t : m.triangles)
    for (std::uint32_t v : t) b.add(m.points[v]);
  return b;
}

double surface_area(const Mesh& m) {
  double a = 0;
  for (const Triangle& t : m.triangles) a += 0.5 * norm(area_normal(m, t));
  return a;
}

double enclosed_volume(const Mesh& m) {
  const BBox3 b = m.bbox();
  const Vec3 o = 0.5 * (b.min + b.max);
  double v = 0;
  for (const Triangle& t : m.triangles) v += volume_term(m, t, o);
  return v / 6;
}

double volume_term(const Mesh& m, const Triangle& t, Vec3 o) {
  return dot(m.points[t[0]] - o, cross(m.points[t[1]] - o, m.points[t[2]] - o));
}

}  // namespace selfsim
