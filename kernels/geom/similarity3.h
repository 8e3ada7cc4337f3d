// Direct similarities of 3D space, p -> M p + t with M a rotation times a positive scale: a 3D curve's
// placement (a turtle's open curve onto (0,0,0)-(1,0,0)) and Curve3:transform's rotations.
#pragma once

#include <array>
#include <cmath>
#include <numbers>

#include "kernels/geom/polyline.h"
#include "kernels/geom/vec3.h"

namespace selfsim {

struct Similarity3 {
  std::array<Vec3, 3> rows{Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};  // M, row by row
  Vec3 t{};

  Vec3 linear(Vec3 p) const { return {dot(rows[0], p), dot(rows[1], p), dot(rows[2], p)}; }
  Vec3 operator()(Vec3 p) const { return linear(p) + t; }
  // The scale factor (M's rows all have this length).
  double scale() const { return norm(rows[0]); }

  // this after `first`.
  Similarity3 after(const Similarity3& first) const {
    Similarity3 out;
    for (int i = 0; i < 3; ++i) {
      const Vec3 r = rows[static_cast<std::size_t>(i)];
      out.rows[static_cast<std::size_t>(i)] = {r.x * first.rows[0].x + r.y * first.rows[1].x + r.z * first.rows[2].x,
                                               r.x * first.rows[0].y + r.y * first.rows[1].y + r.z * first.rows[2].y,
                                               r.x * first.rows[0].z + r.y * first.rows[1].z + r.z * first.rows[2].z};
    }
    out.t = (*this)(first.t);
    return out;
  }

  static Similarity3 scaling(double s) {
    Similarity3 m;
    for (Vec3& r : m.rows) r = s * r;
    return m;
  }

  // The rotation by `degrees` about the unit `axis`, counterclockwise seen from where the axis points
  // (Rodrigues' formula).
  static Similarity3 rotation(Vec3 axis, double degrees) {
    const double a = degrees * std::numbers::pi / 180, c = std::cos(a), s = std::sin(a), k = 1 - c;
    const Vec3 u = axis;
    Similarity3 m;
    m.rows = {Vec3{c + u.x * u.x * k, u.x * u.y * k - u.z * s, u.x * u.z * k + u.y * s},
              Vec3{u.y * u.x * k + u.z * s, c + u.y * u.y * k, u.y * u.z * k - u.x * s},
              Vec3{u.z * u.x * k - u.y * s, u.z * u.y * k + u.x * s, c + u.z * u.z * k}};
    return m;
  }

  // The similarity taking a to (0,0,0) and b to (1,0,0) that turns b - a onto the x axis by the least
  // rotation (about their common perpendicular), so a curve in the xy-plane stays in it. a != b.
  static Similarity3 to_unit(Vec3 a, Vec3 b) {
    const Vec3 d = b - a;
    const double length = norm(d);
    const Vec3 u = d / length, x{1, 0, 0};
    const Vec3 axis = cross(u, x);
    const double sine = norm(axis), cosine = dot(u, x);
    Similarity3 turn;
    if (sine > 1e-300)
      turn = rotation(axis / sine, std::atan2(sine, cosine) * 180 / std::numbers::pi);
    else if (cosine < 0)
      turn = rotation({0, 0, 1}, 180);  // pointing along -x: half a turn within the xy-plane
    Similarity3 m = scaling(1 / length).after(turn);
    m.t = -m.linear(a);
    return m;
  }
};

// c with every point mapped by t (paths and fields kept; length fields scaled with it: length_fields.h).
Polyline3 transformed(const Polyline3& c, const Similarity3& t);

}  // namespace selfsim
