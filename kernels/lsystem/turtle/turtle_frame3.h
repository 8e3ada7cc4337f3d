// The 3D turtle's orientation (ABOP 1.5): heading H, left L and up U, a right-handed orthonormal frame
// (H x L = U). Turns are rotations of two of the vectors in their plane, seen from the turtle:
//   + yaw left    (H toward L)    - yaw right
//   & pitch down  (H toward -U)   ^ pitch up
//   \ roll left   (L toward -U)   / roll right
//   | turn around (H and L reversed)
//   $ roll about H until L is horizontal (perpendicular to `up`)
// A grammar kept in the plane of H and L draws what the 2D turtle draws: yaw left is counterclockwise
// seen from U. A plant starts heading(90): H = +y (up, where `$` and the previews put up), L = -x and
// U = +z, toward a viewer looking down -z with y up; so a plant's front view is the 2D turtle's drawing,
// and + still turns it counterclockwise there.
#pragma once

#include <cmath>
#include <numbers>

#include "kernels/geom/vec3.h"

namespace selfsim::lsystem {

struct TurtleFrame3 {
  Vec3 h{1, 0, 0}, l{0, 1, 0}, u{0, 0, 1};

  // Heading `degrees` counterclockwise from +x in the xy-plane, up +z.
  static TurtleFrame3 heading(double degrees) {
    TurtleFrame3 f;
    f.yaw(degrees);
    return f;
  }

  void yaw(double degrees) { turn(h, l, degrees); }
  void pitch(double degrees) { turn(h, u, -degrees); }
  void roll(double degrees) { turn(l, u, -degrees); }
  void turn_around() {
    h = -h;
    l = -l;
  }
  // L made horizontal: L = up x H / |up x H|, U = H x L. Nothing when H is vertical (no horizontal L is
  // singled out).
  void level(Vec3 up) {
    const Vec3 side = cross(up, h);
    const double n = norm(side);
    if (!(n > 1e-12)) return;
    l = side / n;
    u = cross(h, l);
  }
  // Tropism (ABOP 2.3): H bends toward t by the angle |H x t| (t's length is the elasticity), the frame
  // turning with it about H x t.
  void bend(Vec3 t) {
    const Vec3 axis = cross(h, t);
    const double angle = norm(axis);
    if (!(angle > 1e-15)) return;
    const Vec3 k = axis / angle;
    const double c = std::cos(angle), s = std::sin(angle);
    auto rotate = [&](Vec3 v) { return c * v + s * cross(k, v) + (1 - c) * dot(k, v) * k; };
    h = rotate(h);
    l = rotate(l);
    u = rotate(u);
  }
  // Rounding drifts the frame over millions of turns: made orthonormal again from H and L.
  void orthonormalise() {
    h = normalized(h);
    l = normalized(l - dot(l, h) * h);
    u = cross(h, l);
  }

 private:
  // a toward b by `degrees`, in their plane. Quarter turns are exact, so lattice curves (the 3D Hilbert
  // curve) stay on the lattice.
  static void turn(Vec3& a, Vec3& b, double degrees) {
    double c, s;
    const double d = std::fmod(degrees, 360.0);  // exact
    if (const double q = std::round(d / 90); q * 90 == d) {
      const int k = (static_cast<int>(q) % 4 + 4) % 4;
      c = k == 0 ? 1 : k == 2 ? -1 : 0;
      s = k == 1 ? 1 : k == 3 ? -1 : 0;
    } else {
      const double r = d * std::numbers::pi / 180;
      c = std::cos(r);
      s = std::sin(r);
    }
    const Vec3 a2 = c * a + s * b, b2 = c * b - s * a;
    a = a2;
    b = b2;
  }
};

}  // namespace selfsim::lsystem
