// The one 3D point/vector type of selfsim, beside Vec2: every 3D kernel (turtle, develop, exclusion surfaces)
// uses it, and conversions to OpenMesh, OpenVDB and VTK types happen only at those libraries' boundaries.
#pragma once

#include <cmath>

namespace selfsim {

struct Vec3 {
  double x = 0, y = 0, z = 0;

  // All three coordinates equal to v.
  static constexpr Vec3 all(double v) { return {v, v, v}; }

  friend constexpr Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend constexpr Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend constexpr Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
  friend constexpr Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
  friend constexpr Vec3 operator*(Vec3 a, double s) { return {s * a.x, s * a.y, s * a.z}; }
  friend constexpr Vec3 operator/(Vec3 a, double s) { return {a.x / s, a.y / s, a.z / s}; }
  constexpr Vec3& operator+=(Vec3 b) { return *this = *this + b; }
  constexpr Vec3& operator-=(Vec3 b) { return *this = *this - b; }
  friend constexpr bool operator==(Vec3 a, Vec3 b) = default;
};

constexpr double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline double norm(Vec3 a) { return std::hypot(a.x, a.y, a.z); }
// a at t = 0, b at t = 1.
constexpr Vec3 lerp(Vec3 a, Vec3 b, double t) { return a + t * (b - a); }
// a scaled to length 1; a zero vector stays zero (callers that need a direction check the length first).
inline Vec3 normalized(Vec3 a) {
  const double n = norm(a);
  return n > 0 ? a / n : a;
}
inline bool is_finite(Vec3 a) { return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z); }
constexpr Vec3 min_each(Vec3 a, Vec3 b) {
  return {a.x < b.x ? a.x : b.x, a.y < b.y ? a.y : b.y, a.z < b.z ? a.z : b.z};
}
constexpr Vec3 max_each(Vec3 a, Vec3 b) {
  return {a.x > b.x ? a.x : b.x, a.y > b.y ? a.y : b.y, a.z > b.z ? a.z : b.z};
}

}  // namespace selfsim
