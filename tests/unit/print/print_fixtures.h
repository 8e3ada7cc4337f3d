// Shared by the print check's tests: solids made of two meshes side by side, and a report's findings
// searched for words.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "kernels/geom/mesh.h"
#include "kernels/print/print_check.h"

namespace print_fixtures {

// a and b as one mesh (b's triangles renumbered after a's points): two solids, or a solid and a cavity.
inline selfsim::Mesh joined(const selfsim::Mesh& a, const selfsim::Mesh& b) {
  selfsim::Mesh m = a;
  const auto n = static_cast<std::uint32_t>(a.points.size());
  m.points.insert(m.points.end(), b.points.begin(), b.points.end());
  for (selfsim::Triangle t : b.triangles) m.triangles.push_back({t[0] + n, t[1] + n, t[2] + n});
  return m;
}

// Whether any of r's findings holds `words`.
inline bool mentions(const selfsim::print::PrintReport& r, const std::string& words) {
  return std::any_of(r.findings.begin(), r.findings.end(),
                     [&](const std::string& f) { return f.find(words) != std::string::npos; });
}

// A closed solid of revolution about the z axis, facing outwards: `profile` (radius, z) runs from a point on
// the axis up to another (a mushroom: (0,0), (5,0), (5,10), (15,10), (15,15), (0,15)), each point between a
// ring of `sides` points.
inline selfsim::Mesh revolved(const std::vector<std::pair<double, double>>& profile, int sides) {
  selfsim::Mesh m;
  const auto ring = [&](std::size_t i) { return static_cast<std::uint32_t>(1 + (i - 1) * sides); };
  const std::size_t last = profile.size() - 1;
  m.points.push_back({0, 0, profile.front().second});
  for (std::size_t i = 1; i < last; ++i)
    for (int k = 0; k < sides; ++k) {
      const double a = 2 * 3.14159265358979323846 * k / sides;
      m.points.push_back({profile[i].first * std::cos(a), profile[i].first * std::sin(a), profile[i].second});
    }
  m.points.push_back({0, 0, profile.back().second});
  const auto top = static_cast<std::uint32_t>(m.points.size() - 1);
  for (std::uint32_t k = 0; k < std::uint32_t(sides); ++k) {
    const std::uint32_t next = (k + 1) % sides;
    m.triangles.push_back({0, ring(1) + next, ring(1) + k});
    for (std::size_t i = 1; i + 1 < last; ++i)
      m.triangles.push_back({ring(i) + k, ring(i) + next, ring(i + 1) + next}),
          m.triangles.push_back({ring(i) + k, ring(i + 1) + next, ring(i + 1) + k});
    m.triangles.push_back({ring(last - 1) + k, ring(last - 1) + next, top});
  }
  return m;
}

// A regular polygon's area: `sides` corners on a circle of radius r.
inline double polygon_area(double r, int sides) {
  return 0.5 * sides * r * r * std::sin(2 * 3.14159265358979323846 / sides);
}

}  // namespace print_fixtures
