#include "kernels/geom/mesh_transform.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "kernels/base/check.h"
#include "kernels/base/error.h"
#include "kernels/geom/length_fields.h"

namespace selfsim {

namespace {

bool is_normal_field(const Field& f) {
  if (f.components != 3 || f.scalar() != Scalar::Float64) return false;
  std::string n = f.name;
  std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return n == "normal" || n == "normals";
}

// Normals through the inverse transpose: cof(M) / det(M), whose rows are the cross products of M's rows. The
// length is restored afterwards, so only det's sign matters (it keeps a mirrored outward normal outward).
void map_normals(Fields& fields, const Affine3& a) {
  const double sign = a.determinant() < 0 ? -1 : 1;
  const Affine3 cofactor{
      {sign * cross(a.rows[1], a.rows[2]), sign * cross(a.rows[2], a.rows[0]), sign * cross(a.rows[0], a.rows[1])}};
  for (Field& f : fields.list) {
    if (!is_normal_field(f)) continue;
    std::vector<double>& v = std::get<1>(f.data);
    for (std::size_t i = 0; i + 2 < v.size(); i += 3) {
      const Vec3 n{v[i], v[i + 1], v[i + 2]};
      const Vec3 m = cofactor.linear(n);
      const double length = norm(m);
      const Vec3 out = length > 0 ? (norm(n) / length) * m : m;
      v[i] = out.x, v[i + 1] = out.y, v[i + 2] = out.z;
    }
  }
}

// The factor lengths scale by when a is a similarity (every direction stretched alike), or 0.
double uniform_factor(const Affine3& a) {
  const double k = norm(a.rows[0]);
  const double tolerance = 1e-12 * k;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double d = dot(a.rows[static_cast<std::size_t>(i)], a.rows[static_cast<std::size_t>(j)]);
      if (std::abs(d - (i == j ? k * k : 0)) > tolerance * k) return 0;
    }
  return k;
}

// Whether a keeps every face's tilt from the horizontal: a similarity that keeps +z up (rows' z column
// (0, 0, k), k > 0): a turn about z, a uniform scale, a mirror across a vertical plane.
bool keeps_up(const Affine3& a) {
  const double k = uniform_factor(a);
  if (!(k > 0)) return false;
  const double tolerance = 1e-12 * k;
  return std::abs(a.rows[0].z) <= tolerance && std::abs(a.rows[1].z) <= tolerance &&
         std::abs(a.rows[2].z - k) <= tolerance;
}

// Drops fields named `overhang` (any case): the print check's degrees below horizontal, measured against
// the old +z, wrong once the solid tilts.
void drop_overhang_fields(Fields& fields) {
  std::erase_if(fields.list, [](const Field& f) {
    std::string n = f.name;
    std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return n == "overhang";
  });
}

}  // namespace

void MeshTransform::validate() const {
  for (double s : {scale.x, scale.y, scale.z})
    if (!(s != 0) || !std::isfinite(s))
      throw Error("option 'scale' must be a non-zero finite factor (or {sx, sy, sz} of them), got " + number_text(s));
  if (!std::isfinite(degrees)) throw Error("option 'rotate' must be finite degrees, got " + number_text(degrees));
  if (!is_finite(axis) || !(norm(axis) > 0)) throw Error("option 'axis' must be a non-zero finite vector {x, y, z}");
  if (!is_finite(translate)) throw Error("option 'translate' must be a finite {x, y, z}");
}

Affine3 rotation(Vec3 u, double degrees) {
  const double a = std::fmod(degrees, 360.0) * std::numbers::pi / 180, c = std::cos(a), s = std::sin(a), k = 1 - c;
  Affine3 r;
  r.rows = {Vec3{c + u.x * u.x * k, u.x * u.y * k - u.z * s, u.x * u.z * k + u.y * s},
            Vec3{u.y * u.x * k + u.z * s, c + u.y * u.y * k, u.y * u.z * k - u.x * s},
            Vec3{u.z * u.x * k - u.y * s, u.z * u.y * k + u.x * s, c + u.z * u.z * k}};
  return r;
}

Affine3 MeshTransform::map() const {
  validate();
  Affine3 m = rotation(axis / norm(axis), degrees);
  for (Vec3& r : m.rows) r = {r.x * scale.x, r.y * scale.y, r.z * scale.z};  // R times diag(scale)
  m.t = translate;
  return m;
}

Mesh transformed(const Mesh& m, const Affine3& a, Progress& progress) {
  Mesh out = m;
  for (std::size_t i = 0; i < out.points.size(); ++i) {
    if ((i & 0xffff) == 0xffff && progress.cancelled()) throw Cancelled();
    out.points[i] = a(out.points[i]);
  }
  if (!out.finite()) throw Error("the transformed mesh overflows (its coordinates pass the largest number)");
  if (a.determinant() < 0)
    for (Triangle& t : out.triangles) std::swap(t[1], t[2]);  // a mirror: keep facing outwards
  for (Fields* fields : {&out.point_fields, &out.face_fields}) {
    map_normals(*fields, a);
    scale_length_fields(*fields, uniform_factor(a));
    if (!keeps_up(a)) drop_overhang_fields(*fields);
  }
  return out;
}

}  // namespace selfsim
