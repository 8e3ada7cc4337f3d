#include "kernels/geom/triangle_bvh.h"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <atomic>
#include <cmath>

#include "kernels/base/error.h"

namespace selfsim {

namespace {

constexpr std::uint32_t leaf_size = 4;
// Ranges longer than this build their two halves at once (tbb), and look for a stop.
constexpr std::size_t parallel_from = 16384;
// A hit may lie this far outside a triangle, in barycentric terms: a ray through a shared edge is not lost
// between the two triangles to rounding (the caller merges the two crossings it then reads).
constexpr double edge_tolerance = 1e-9;

struct Item {
  Vec3 centre;
  std::uint32_t face;
};

double axis(Vec3 v, int k) { return k == 0 ? v.x : k == 1 ? v.y : v.z; }

struct Builder {
  const Mesh& m;
  std::vector<Item>& items;  // 32 bytes each: what the splits move about
  double pad;                // every box is this much wider each way
  Progress& progress;
  std::atomic<bool> stop{false};

  struct Built {
    std::size_t depth;
    Vec3 lo, hi;  // the subtree's triangles' box (its node's, less the pad)
  };

  // Appends the subtree over items [first, last) to `out`. Boxes are made from the leaves up: a leaf's from
  // its triangles' corners (its items are in their last places by then), a node's from its children's.
  Built build(std::size_t first, std::size_t last, std::vector<TriangleBvh::Node>& out) {
    const std::size_t n = last - first;
    const std::size_t me = out.size();
    out.emplace_back();
    const auto finish = [&](std::size_t depth, Vec3 lo, Vec3 hi) {
      out[me].lo = lo - Vec3::all(pad);
      out[me].hi = hi + Vec3::all(pad);
      return Built{depth, lo, hi};
    };
    if (n <= leaf_size) {
      Vec3 lo = Vec3::all(HUGE_VAL), hi = Vec3::all(-HUGE_VAL);
      for (std::size_t i = first; i < last; ++i)
        for (std::uint32_t v : m.triangles[items[i].face]) {
          lo = min_each(lo, m.points[v]);
          hi = max_each(hi, m.points[v]);
        }
      out[me].first = static_cast<std::uint32_t>(first);
      out[me].count = static_cast<std::uint32_t>(n);
      return finish(1, lo, hi);
    }
    if (n >= parallel_from && (stop || progress.cancelled())) {
      stop = true;
      return {1, {}, {}};
    }
    // The median of the centres along the box of centres' longest side.
    Vec3 clo = items[first].centre, chi = clo;
    for (std::size_t i = first + 1; i < last; ++i) {
      clo = min_each(clo, items[i].centre);
      chi = max_each(chi, items[i].centre);
    }
    const Vec3 extent = chi - clo;
    const int k = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    const std::size_t mid = first + n / 2;
    std::nth_element(items.begin() + static_cast<std::ptrdiff_t>(first),
                     items.begin() + static_cast<std::ptrdiff_t>(mid),
                     items.begin() + static_cast<std::ptrdiff_t>(last),
                     [k](const Item& a, const Item& b) { return axis(a.centre, k) < axis(b.centre, k); });
    Built left{}, right{};
    if (n < parallel_from) {
      left = build(first, mid, out);
      out[me].first = static_cast<std::uint32_t>(out.size() - me);
      right = build(mid, last, out);
    } else {
      std::vector<TriangleBvh::Node> a, b;
      tbb::parallel_invoke([&] { left = build(first, mid, a); }, [&] { right = build(mid, last, b); });
      out[me].first = static_cast<std::uint32_t>(1 + a.size());
      out.insert(out.end(), a.begin(), a.end());
      out.insert(out.end(), b.begin(), b.end());
    }
    return finish(1 + std::max(left.depth, right.depth), min_each(left.lo, right.lo), max_each(left.hi, right.hi));
  }
};

}  // namespace

double TriangleBvh::size(std::size_t triangles) {
  // Per triangle: its item while building (32 bytes), its copy for the rays (80), and up to one node (56),
  // twice while the halves built apart are joined: 224 bytes; 17 points of 16 leave room.
  return 17.0 * static_cast<double>(triangles) + 1024;
}

TriangleBvh::TriangleBvh(const Mesh& m, Progress& progress) {
  if (m.faces() >= UINT32_MAX / 2) throw Error("internal error: TriangleBvh holds under 2^31 triangles");
  std::vector<Item> items;
  items.reserve(m.faces());
  Vec3 lo = Vec3::all(HUGE_VAL), hi = Vec3::all(-HUGE_VAL);
  for (std::uint32_t f = 0; f < m.faces(); ++f) {
    const Vec3 a = m.points[m.triangles[f][0]], b = m.points[m.triangles[f][1]], c = m.points[m.triangles[f][2]];
    const Vec3 n = cross(b - a, c - a);
    if (!(dot(n, n) > 0) || !is_finite(n)) continue;  // no area: nothing crosses it
    items.push_back({(1.0 / 3) * (a + b + c), f});
    lo = min_each(lo, min_each(a, min_each(b, c)));
    hi = max_each(hi, max_each(a, max_each(b, c)));
  }
  if (items.empty()) return;
  // Boxes a little wider than their triangles: the slab test's rounding never drops a ray that touches one.
  const Vec3 whole = hi - lo;
  Builder builder{m, items, 1e-9 * std::max({whole.x, whole.y, whole.z, 1e-300}), progress};
  nodes_.reserve(items.size());
  depth_ = builder.build(0, items.size(), nodes_).depth;
  if (builder.stop || progress.cancelled()) throw Cancelled();
  tris_.reserve(items.size());
  for (const Item& it : items) {
    const Triangle& t = m.triangles[it.face];
    const Vec3 a = m.points[t[0]];
    tris_.push_back({a, m.points[t[1]] - a, m.points[t[2]] - a, it.face});
  }
}

void TriangleBvh::crossings(Vec3 origin, Vec3 dir, double tmin, double tmax, std::vector<Hit>& hits) const {
  crossings(std::span<const Vec3>(&origin, 1), dir, tmin, tmax, hits);
}

bool TriangleBvh::crossings(std::span<const Vec3> origins, Vec3 dir, double tmin, double tmax, std::vector<Hit>& hits,
                            std::size_t most) const {
  if (nodes_.empty() || origins.empty()) return true;
  const std::size_t had = hits.size();
  std::size_t opened = 0;
  // The rays as one thick ray: the middle one, with its parameters widened by how far along dir the others
  // start, and every box widened by how far across it they lie (a box of that half-width holds the ball).
  Vec3 centre{};
  for (const Vec3& o : origins) centre += o;
  centre = (1.0 / static_cast<double>(origins.size())) * centre;
  double lo_t = tmin, hi_t = tmax, across = 0;
  for (const Vec3& o : origins) {
    const Vec3 off = o - centre;
    const double along = dot(off, dir);
    lo_t = std::min(lo_t, tmin + along);
    hi_t = std::max(hi_t, tmax + along);
    across = std::max(across, norm(off - along * dir));
  }
  // Slabs: the segment (lo_t, hi_t] meets a box where its three intervals between the box's planes overlap.
  // An axis the ray does not move along has 1/0 = inf: its interval is everything or (where the origin lies
  // on the box's plane, inf · 0) NaN, which std::max and std::min below pass over (NaN compares false).
  const Vec3 inv{1 / dir.x, 1 / dir.y, 1 / dir.z};
  const Vec3 widen = Vec3::all(across);
  const auto meets = [&](const Node& n) {
    const Vec3 a = n.lo - widen - centre, b = n.hi + widen - centre;
    const auto slab = [](double lo, double hi, double inv) {
      const double x = lo * inv, y = hi * inv;
      return inv >= 0 ? std::pair{x, y} : std::pair{y, x};
    };
    const auto [x0, x1] = slab(a.x, b.x, inv.x);
    const auto [y0, y1] = slab(a.y, b.y, inv.y);
    const auto [z0, z1] = slab(a.z, b.z, inv.z);
    const double t0 = std::max(std::max(std::max(lo_t, x0), y0), z0);
    const double t1 = std::min(std::min(std::min(hi_t, x1), y1), z1);
    return t0 <= t1;
  };
  std::uint32_t stack[128];
  std::size_t top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const std::uint32_t i = stack[--top];
    const Node& n = nodes_[i];
    if (++opened + (hits.size() - had) > most) return false;
    if (!meets(n)) continue;
    if (n.count == 0) {
      stack[top++] = i + n.first;
      stack[top++] = i + 1;
      continue;
    }
    for (std::uint32_t j = n.first; j < n.first + n.count; ++j) {
      // Möller and Trumbore: the crossing's barycentric coordinates (u, v) and parameter t by Cramer's rule;
      // what depends on the direction alone is shared by the rays.
      const Tri& tri = tris_[j];
      const Vec3 p = cross(dir, tri.ac);
      const double det = dot(tri.ab, p);
      if (det == 0) continue;  // the rays run in the triangle's plane
      const double inv_det = 1 / det;
      double facing = 2;  // worked out at the first crossing
      for (std::size_t k = 0; k < origins.size(); ++k) {
        const Vec3 s = origins[k] - tri.a;
        const double u = dot(s, p) * inv_det;
        if (u < -edge_tolerance || u > 1 + edge_tolerance) continue;
        const Vec3 q = cross(s, tri.ab);
        const double v = dot(dir, q) * inv_det;
        if (v < -edge_tolerance || u + v > 1 + edge_tolerance) continue;
        const double t = dot(tri.ac, q) * inv_det;
        if (!(t > tmin && t <= tmax)) continue;
        if (facing > 1) {
          const Vec3 normal = cross(tri.ab, tri.ac);
          facing = dot(normal, dir) / std::sqrt(dot(normal, normal));
        }
        hits.push_back({t, tri.face, facing, static_cast<std::uint32_t>(k)});
      }
    }
  }
  return true;
}

}  // namespace selfsim
