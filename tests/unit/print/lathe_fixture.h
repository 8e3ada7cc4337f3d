// Solids of revolution for the overhang and orientation tests: a profile of rings (radius, height) around
// the z axis, from a centre point below the first ring to one above the last, as a closed mesh facing
// outwards. A cube, a mushroom (a stem under a wider cap) and a sphere are each a few rings.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <utility>
#include <vector>

#include "kernels/geom/mesh.h"

namespace lathe_fixture {

struct Ring {
  double radius, z;
};

// The rings' polygons of `sides` corners (the first at angle `phase`, degrees), closed by a fan at
// `bottom` and one at `top` (the heights of the centre points on the axis).
inline selfsim::Mesh lathe(const std::vector<Ring>& rings, double bottom, double top, int sides, double phase = 0) {
  selfsim::Mesh m;
  const auto n = static_cast<std::uint32_t>(sides);
  m.points.push_back({0, 0, bottom});
  for (const Ring& r : rings)
    for (int j = 0; j < sides; ++j) {
      const double a = (phase + 360.0 * j / sides) * std::numbers::pi / 180;
      m.points.push_back({r.radius * std::cos(a), r.radius * std::sin(a), r.z});
    }
  const auto last = static_cast<std::uint32_t>(m.points.size());
  m.points.push_back({0, 0, top});
  auto at = [&](std::size_t ring, std::uint32_t j) { return static_cast<std::uint32_t>(1 + ring * n + j % n); };
  for (std::uint32_t j = 0; j < n; ++j) m.triangles.push_back({0, at(0, j + 1), at(0, j)});
  for (std::size_t r = 0; r + 1 < rings.size(); ++r)
    for (std::uint32_t j = 0; j < n; ++j) {
      m.triangles.push_back({at(r, j), at(r, j + 1), at(r + 1, j + 1)});
      m.triangles.push_back({at(r, j), at(r + 1, j + 1), at(r + 1, j)});
    }
  for (std::uint32_t j = 0; j < n; ++j)
    m.triangles.push_back({last, at(rings.size() - 1, j), at(rings.size() - 1, j + 1)});
  return m;
}

// The area of the regular polygon of `sides` corners on a circle of radius r.
inline double polygon_area(int sides, double r) { return sides / 2.0 * std::sin(2 * std::numbers::pi / sides) * r * r; }

// An axis-aligned box from (-a/2, -a/2, 0) to (a/2, a/2, h) (four sides turned 45 degrees).
inline selfsim::Mesh box(double a, double h) {
  const double r = a / std::sqrt(2.0);
  return lathe({{r, 0}, {r, h}}, 0, h, 4, 45);
}

// A stem of radius `stem` from z = 0 to 10 under a cap of radius `cap` from 10 to 14, 32 sides.
inline selfsim::Mesh mushroom(double stem = 3, double cap = 10) {
  return lathe({{stem, 0}, {stem, 10}, {cap, 10}, {cap, 14}}, 0, 14, 32);
}

// A sphere of radius r about the origin: `bands` rings of latitude between the poles, 64 sides.
inline selfsim::Mesh sphere(double r, int bands = 48) {
  std::vector<Ring> rings;
  for (int i = 1; i < bands; ++i) {
    const double a = -std::numbers::pi / 2 + std::numbers::pi * i / bands;
    rings.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return lathe(rings, -r, r, 64);
}

}  // namespace lathe_fixture
