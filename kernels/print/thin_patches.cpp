#include "kernels/print/thin_patches.h"

#include <algorithm>
#include <cstdint>
#include <numeric>

namespace selfsim::print {

namespace {

std::uint32_t root(std::vector<std::uint32_t>& parent, std::uint32_t f) {
  while (parent[f] != f) f = parent[f] = parent[parent[f]];
  return f;
}

}  // namespace

Patches thin_patches(const Mesh& m, const std::vector<char>& flagged) {
  constexpr std::uint32_t none = 0xffffffffu;
  std::vector<std::uint32_t> parent(m.faces());
  std::iota(parent.begin(), parent.end(), 0u);
  std::vector<std::uint32_t> first(m.points.size(), none);  // the first flagged face at each point
  for (std::uint32_t f = 0; f < m.faces(); ++f) {
    if (!flagged[f]) continue;
    for (std::uint32_t v : m.triangles[f]) {
      if (first[v] == none) {
        first[v] = f;
        continue;
      }
      const std::uint32_t a = root(parent, first[v]), b = root(parent, f);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  }
  std::vector<double> area(m.faces(), 0);
  Patches p;
  for (std::uint32_t f = 0; f < m.faces(); ++f)
    if (flagged[f]) {
      const std::uint32_t r = root(parent, f);
      p.count += r == f;
      double& a = area[r];
      a += 0.5 * norm(area_normal(m, m.triangles[f]));
      p.largest = std::max(p.largest, a);
    }
  return p;
}

}  // namespace selfsim::print
