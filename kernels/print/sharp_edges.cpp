#include "kernels/print/sharp_edges.h"

#include <tbb/parallel_sort.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace selfsim::print {

namespace {

// Normals closer than 25 degrees: a smooth stretch. A ray from beside an edge turning more than that runs
// close enough to the face beyond for the grid's error to matter (a 16-sided tube, 22.5 degrees a side, is
// smooth).
constexpr double smooth_cos = 0.906;

double segment_distance(Vec3 p, Vec3 a, Vec3 b) {
  const Vec3 ab = b - a;
  const double length2 = dot(ab, ab);
  const double t = length2 > 0 ? std::clamp(dot(p - a, ab) / length2, 0.0, 1.0) : 0;
  return norm(p - (a + t * ab));
}

std::uint32_t root(std::vector<std::uint32_t>& parent, std::uint32_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

SharpEdges::SharpEdges(const Mesh& m, double reach) : reach_(reach), cell_(reach), origin_(m.bbox().min) {
  // Each edge's triangles: (lower point, higher point, triangle), sorted so an edge's are side by side.
  struct Side {
    std::uint32_t a, b, face;
  };
  std::vector<Side> sides;
  sides.reserve(3 * m.faces());
  for (std::uint32_t f = 0; f < m.faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const auto [a, b] = std::minmax(m.triangles[f][k], m.triangles[f][(k + 1) % 3]);
      sides.push_back({a, b, f});
    }
  tbb::parallel_sort(sides.begin(), sides.end(),
                     [](const Side& x, const Side& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
  std::vector<std::uint32_t> parent(m.faces());
  std::iota(parent.begin(), parent.end(), 0u);
  const auto unit = [&](std::uint32_t f) { return normalized(area_normal(m, m.triangles[f])); };
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i;
    while (j < sides.size() && sides[j].a == sides[i].a && sides[j].b == sides[i].b) ++j;
    bool sharp = j - i != 2;
    if (!sharp) {
      const Vec3 n1 = unit(sides[i].face), n2 = unit(sides[i + 1].face);
      // A degenerate triangle has no normal: it joins its neighbours (a mesher's needle is no edge).
      sharp = n1 != Vec3{} && n2 != Vec3{} && dot(n1, n2) < smooth_cos;
      if (!sharp) parent[root(parent, sides[i].face)] = root(parent, sides[i + 1].face);
    }
    if (sharp) edges_.push_back({m.points[sides[i].a], m.points[sides[i].b]});
    i = j;
  }
  patch_.resize(m.faces());
  std::vector<std::uint32_t> number(m.faces(), UINT32_MAX);
  for (std::uint32_t f = 0; f < m.faces(); ++f) {
    std::uint32_t& n = number[root(parent, f)];
    if (n == UINT32_MAX) n = patch_count_++;
    patch_[f] = n;
  }
  // Each edge in the cells (reach wide) its pieces (at most a cell long) cross, so a point's edges within
  // reach are in its cell's 27.
  for (std::uint32_t e = 0; e < edges_.size(); ++e) {
    const auto [a, b] = edges_[e];
    const int pieces = std::max(1, static_cast<int>(std::ceil(norm(b - a) / cell_)));
    for (int k = 0; k < pieces; ++k) {
      const Vec3 p = a + (double(k) / pieces) * (b - a), q = a + (double(k + 1) / pieces) * (b - a);
      const Vec3 lo = (1 / cell_) * (min_each(p, q) - origin_), hi = (1 / cell_) * (max_each(p, q) - origin_);
      for (long x = std::lround(std::floor(lo.x)); x <= std::lround(std::floor(hi.x)); ++x)
        for (long y = std::lround(std::floor(lo.y)); y <= std::lround(std::floor(hi.y)); ++y)
          for (long z = std::lround(std::floor(lo.z)); z <= std::lround(std::floor(hi.z)); ++z)
            cells_.push_back({key(x, y, z), e});
    }
  }
  tbb::parallel_sort(cells_.begin(), cells_.end());
  cells_.erase(std::unique(cells_.begin(), cells_.end()), cells_.end());
}

// Cells are numbered from the box's corner, one cell out on each side; the check's grid holds under 2^20
// voxels across (print_check.cpp), and cells are at least a voxel: 21 bits an axis.
std::uint64_t SharpEdges::key(long x, long y, long z) const {
  return std::uint64_t(x + 1) | std::uint64_t(y + 1) << 21 | std::uint64_t(z + 1) << 42;
}

double SharpEdges::distance(Vec3 p) const {
  double best = reach_;
  const Vec3 c = (1 / cell_) * (p - origin_);
  const long cx = std::lround(std::floor(c.x)), cy = std::lround(std::floor(c.y)), cz = std::lround(std::floor(c.z));
  // x is the key's lowest part: the three cells along x are one run of keys, found with one search.
  for (long y = std::max(cy - 1, -1L); y <= cy + 1; ++y)
    for (long z = std::max(cz - 1, -1L); z <= cz + 1; ++z) {
      const std::uint64_t last = key(cx + 1, y, z);
      auto it = std::lower_bound(cells_.begin(), cells_.end(),
                                 std::pair<std::uint64_t, std::uint32_t>{key(std::max(cx - 1, -1L), y, z), 0});
      for (; it != cells_.end() && it->first <= last; ++it)
        best = std::min(best, segment_distance(p, edges_[it->second].first, edges_[it->second].second));
    }
  return best;
}

}  // namespace selfsim::print
