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

}  // namespace print_fixtures
