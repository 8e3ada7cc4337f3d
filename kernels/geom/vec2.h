// The one 2D point/vector type of selfsim. Similarity maps of the plane read best as complex numbers
// (seed 003: T(z) = a·z + b), so Vec2 multiplies and divides as a complex number does.
#pragma once

#include <cmath>

namespace selfsim {

struct Vec2 {
  double x = 0, y = 0;

  // Both coordinates equal to v.
  static constexpr Vec2 all(double v) { return {v, v}; }

  friend constexpr Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
  friend constexpr Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
  friend constexpr Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }
  friend constexpr Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
  friend constexpr Vec2 operator*(Vec2 a, double s) { return {s * a.x, s * a.y}; }
  // Complex product: rotates a by b's angle and scales by |b|.
  friend constexpr Vec2 operator*(Vec2 a, Vec2 b) { return {a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x}; }
  // Complex quotient; b must be non-zero.
  friend constexpr Vec2 operator/(Vec2 a, Vec2 b) {
    const double d = b.x * b.x + b.y * b.y;
    return {(a.x * b.x + a.y * b.y) / d, (a.y * b.x - a.x * b.y) / d};
  }
  constexpr Vec2& operator+=(Vec2 b) {
    x += b.x;
    y += b.y;
    return *this;
  }
  friend constexpr bool operator==(Vec2 a, Vec2 b) = default;
};

constexpr Vec2 conj(Vec2 a) { return {a.x, -a.y}; }
constexpr double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
constexpr double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
inline double norm(Vec2 a) { return std::hypot(a.x, a.y); }
inline bool is_finite(Vec2 a) { return std::isfinite(a.x) && std::isfinite(a.y); }
constexpr Vec2 lerp(Vec2 a, Vec2 b, double t) { return a + t * (b - a); }
constexpr Vec2 min_each(Vec2 a, Vec2 b) { return {a.x < b.x ? a.x : b.x, a.y < b.y ? a.y : b.y}; }
constexpr Vec2 max_each(Vec2 a, Vec2 b) { return {a.x > b.x ? a.x : b.x, a.y > b.y ? a.y : b.y}; }
// Unit vector at an angle in radians.
inline Vec2 polar(double radians) { return {std::cos(radians), std::sin(radians)}; }

}  // namespace selfsim
