#include "kernels/develop/loop_subdivision.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <tuple>
#include <type_traits>
#include <variant>
#include <vector>

#include "kernels/base/cancellable_sort.h"
#include "kernels/base/check.h"
#include "kernels/base/error.h"
#include "kernels/geom/mesh_check.h"

namespace selfsim::develop {

namespace {

constexpr std::uint32_t none = 0xffffffffu;

// The undirected edges of a mesh, each with the points opposite it in its one or two triangles, and for
// every triangle the index of its edges ab, bc, ca. Built by sorting, so the numbering is deterministic.
struct Edges {
  std::vector<std::uint32_t> a, b, c, d;  // ends a < b; opposite points c (first face), d (second or none)
  std::vector<std::array<std::uint32_t, 3>> of_face;

  Edges(const Mesh& m, Progress& progress) {
    struct Side {
      std::uint32_t lo, hi, face, corner;  // corner: which edge of the face (0: v0v1, 1: v1v2, 2: v2v0)
    };
    std::vector<Side> sides;
    sides.reserve(3 * m.faces());
    for (std::uint32_t f = 0; f < m.faces(); ++f)
      for (std::uint32_t k = 0; k < 3; ++k) {
        const std::uint32_t u = m.triangles[f][k], v = m.triangles[f][(k + 1) % 3];
        sides.push_back({std::min(u, v), std::max(u, v), f, k});
      }
    cancellable_sort(
        sides.begin(), sides.end(),
        [](const Side& x, const Side& y) { return std::tie(x.lo, x.hi, x.face) < std::tie(y.lo, y.hi, y.face); },
        progress);
    of_face.resize(m.faces());
    for (std::size_t i = 0; i < sides.size();) {
      std::size_t j = i + 1;
      while (j < sides.size() && sides[j].lo == sides[i].lo && sides[j].hi == sides[i].hi) ++j;
      const auto e = static_cast<std::uint32_t>(a.size());
      a.push_back(sides[i].lo);
      b.push_back(sides[i].hi);
      auto opposite = [&](const Side& s) { return m.triangles[s.face][(s.corner + 2) % 3]; };
      c.push_back(opposite(sides[i]));
      d.push_back(j - i == 2 ? opposite(sides[i + 1]) : none);
      for (std::size_t k = i; k < j; ++k) of_face[sides[k].face][sides[k].corner] = e;
      i = j;
    }
  }
  std::size_t size() const { return a.size(); }
};

// One round: the weights of every new point as (source point, weight) pairs, applied to positions and to
// every point field alike.
struct Stencils {
  std::vector<std::size_t> begin{0};
  std::vector<std::uint32_t> source;
  std::vector<double> weight;

  void add(std::uint32_t s, double w) {
    source.push_back(s);
    weight.push_back(w);
  }
  void close() { begin.push_back(source.size()); }
};

// The ring of every interior point of valence ≥ 7, in order around it (empty for other points): what the
// bounded rules need. A face (v, x, y) says y follows x around v.
std::vector<std::vector<std::uint32_t>> extraordinary_rings(const Mesh& m,
                                                            const std::vector<std::vector<std::uint32_t>>& neighbours,
                                                            const std::vector<std::vector<std::uint32_t>>& boundary) {
  const std::size_t n = m.points.size();
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> follows(n);
  for (const Triangle& t : m.triangles)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = t[k];
      if (neighbours[v].size() >= 7 && boundary[v].empty()) follows[v].push_back({t[(k + 1) % 3], t[(k + 2) % 3]});
    }
  std::vector<std::vector<std::uint32_t>> rings(n);
  for (std::size_t v = 0; v < n; ++v) {
    auto& f = follows[v];
    if (f.empty()) continue;
    std::sort(f.begin(), f.end());
    std::uint32_t x = f.front().first;
    for (std::size_t k = 0; k < f.size(); ++k) {
      rings[v].push_back(x);
      x = std::lower_bound(f.begin(), f.end(), std::pair<std::uint32_t, std::uint32_t>{x, 0})->second;
    }
  }
  return rings;
}

// Adds the bounded rule's weights, times `share`, for the new point on the edge from v to u; masks[n] caches
// the mask of valence n.
void add_bounded_edge(Stencils& s, std::uint32_t v, std::uint32_t u, const std::vector<std::uint32_t>& ring,
                      double share, std::vector<EdgeMask>& masks) {
  const std::size_t n = ring.size();
  if (masks.size() <= n) masks.resize(n + 1);
  if (masks[n].ring.empty()) masks[n] = bounded_edge_mask(n);
  const EdgeMask& mask = masks[n];
  const std::size_t i = static_cast<std::size_t>(std::find(ring.begin(), ring.end(), u) - ring.begin());
  s.add(v, share * mask.centre);
  for (std::size_t j = 0; j < n; ++j) s.add(ring[j], share * mask.ring[(j + n - i) % n]);
}

Stencils stencils(const Mesh& m, const Edges& e, const std::vector<std::uint32_t>& corners, bool bounded,
                  Progress& progress) {
  const std::size_t n = m.points.size();
  std::vector<char> corner(n, 0);
  for (std::uint32_t v : corners)
    if (v < n) corner[v] = 1;
  std::vector<std::vector<std::uint32_t>> neighbours(n), boundary(n);
  std::vector<std::uint32_t> faces_at(n, 0);
  for (const Triangle& t : m.triangles)
    for (std::uint32_t v : t) ++faces_at[v];
  for (std::size_t i = 0; i < e.size(); ++i) {
    neighbours[e.a[i]].push_back(e.b[i]);
    neighbours[e.b[i]].push_back(e.a[i]);
    if (e.d[i] == none) {
      boundary[e.a[i]].push_back(e.b[i]);
      boundary[e.b[i]].push_back(e.a[i]);
    }
  }
  const auto rings =
      bounded ? extraordinary_rings(m, neighbours, boundary) : std::vector<std::vector<std::uint32_t>>(n);
  std::vector<EdgeMask> masks;
  Stencils s;
  for (std::uint32_t v = 0; v < n; ++v) {
    if ((v & 0xffff) == 0xffff && progress.cancelled()) throw Cancelled();
    if (!boundary[v].empty() && (faces_at[v] == 1 || corner[v])) {
      s.add(v, 1);  // a corner stays
    } else if (!boundary[v].empty()) {
      s.add(v, 0.75);
      for (std::uint32_t u : boundary[v]) s.add(u, 0.125);
    } else if (!neighbours[v].empty()) {
      const double beta = rings[v].empty() ? loop_beta(neighbours[v].size()) : bounded_beta(rings[v].size());
      s.add(v, 1 - static_cast<double>(neighbours[v].size()) * beta);
      for (std::uint32_t u : neighbours[v]) s.add(u, beta);
    } else {
      s.add(v, 1);  // a point no triangle uses
    }
    s.close();
  }
  for (std::size_t i = 0; i < e.size(); ++i) {
    if ((i & 0xffff) == 0xffff && progress.cancelled()) throw Cancelled();
    if (e.d[i] == none) {
      s.add(e.a[i], 0.5);
      s.add(e.b[i], 0.5);
    } else if (!rings[e.a[i]].empty() || !rings[e.b[i]].empty()) {
      const double share = !rings[e.a[i]].empty() && !rings[e.b[i]].empty() ? 0.5 : 1;
      if (!rings[e.a[i]].empty()) add_bounded_edge(s, e.a[i], e.b[i], rings[e.a[i]], share, masks);
      if (!rings[e.b[i]].empty()) add_bounded_edge(s, e.b[i], e.a[i], rings[e.b[i]], share, masks);
    } else {
      s.add(e.a[i], 0.375);
      s.add(e.b[i], 0.375);
      s.add(e.c[i], 0.125);
      s.add(e.d[i], 0.125);
    }
    s.close();
  }
  return s;
}

Mesh one_round(const Mesh& m, const LoopOptions& opt, Progress& progress) {
  const Edges e(m, progress);
  const Stencils s = stencils(m, e, opt.corners, opt.bounded, progress);
  const std::size_t points = m.points.size() + e.size();
  Mesh out;
  out.points.resize(points);
  for (std::size_t p = 0; p < points; ++p) {
    if ((p & 0xffff) == 0 && progress.cancelled()) throw Cancelled();
    Vec3 sum{};
    for (std::size_t k = s.begin[p]; k < s.begin[p + 1]; ++k) sum = sum + s.weight[k] * m.points[s.source[k]];
    out.points[p] = sum;
  }
  for (const Field& f : m.point_fields.list) {
    std::vector<double> values(points * static_cast<std::size_t>(f.components));
    for (std::size_t p = 0; p < points; ++p)
      for (int c = 0; c < f.components; ++c) {
        if ((p & 0xffff) == 0 && c == 0 && progress.cancelled()) throw Cancelled();
        double sum = 0;
        for (std::size_t k = s.begin[p]; k < s.begin[p + 1]; ++k) sum += s.weight[k] * f.at(s.source[k], c);
        values[p * static_cast<std::size_t>(f.components) + static_cast<std::size_t>(c)] = sum;
      }
    out.point_fields.set(real_field(f.name, std::move(values), f.components));
  }
  // Each triangle v0 v1 v2 with edge points e01 e12 e20 becomes (v0 e01 e20), (v1 e12 e01), (v2 e20 e12),
  // (e01 e12 e20): the same orientation.
  const auto base = static_cast<std::uint32_t>(m.points.size());
  out.triangles.reserve(4 * m.faces());
  for (std::size_t f = 0; f < m.faces(); ++f) {
    if ((f & 0xffff) == 0 && progress.cancelled()) throw Cancelled();
    const Triangle& t = m.triangles[f];
    const std::uint32_t e01 = base + e.of_face[f][0], e12 = base + e.of_face[f][1], e20 = base + e.of_face[f][2];
    out.triangles.push_back({t[0], e01, e20});
    out.triangles.push_back({t[1], e12, e01});
    out.triangles.push_back({t[2], e20, e12});
    out.triangles.push_back({e01, e12, e20});
  }
  // The four children of face f are faces 4f .. 4f + 3, each with f's fields.
  std::vector<std::uint32_t> parent(4 * m.faces());
  for (std::size_t k = 0; k < parent.size(); ++k) parent[k] = static_cast<std::uint32_t>(k / 4);
  out.face_fields = picked_fields<std::uint32_t>(m.face_fields, parent, progress);
  return out;
}

}  // namespace

void LoopOptions::validate() const { check_range(steps, 0, 12, "option 'smooth'"); }

double loop_beta(std::size_t valence) {
  const double n = static_cast<double>(valence);
  const double x = 0.375 + 0.25 * std::cos(2 * std::numbers::pi / n);
  return (0.625 - x * x) / n;
}

namespace {

double subdominant(double n) { return 0.375 + 0.25 * std::cos(2 * std::numbers::pi / n); }

}  // namespace

EdgeMask bounded_edge_mask(std::size_t valence) {
  const std::size_t n = std::max<std::size_t>(valence, 3);
  EdgeMask mask;
  mask.ring.assign(n, 0);
  if (n < 7) {
    mask.centre = 0.375;
    mask.ring[0] = 0.375;
    mask.ring[1] += 0.125;
    mask.ring[n - 1] += 0.125;
    return mask;
  }
  const double l = subdominant(static_cast<double>(n));
  const double r = (3 * l - 2) / (2 * l), c3 = l * l * l / (4 - 4 * l);
  mask.centre = 1 - (2 * l * l + l * (3 * l - 2) * (3 * l - 2) / (2 * (1 - l)));
  for (std::size_t k = 0; k < n; ++k) {
    const double x = std::cos(2 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(n));
    mask.ring[k] = 8 * c3 * (x + 1) * (x - r) * (x - r) / static_cast<double>(n);
  }
  return mask;
}

double bounded_beta(std::size_t valence) {
  if (valence < 7) return loop_beta(valence);
  const double l = subdominant(static_cast<double>(valence));
  return (1 - bounded_edge_mask(valence).centre - l * l) / static_cast<double>(valence);
}

namespace {

double size_after(double v, double e, double f, int steps) {
  for (int i = 0; i < steps; ++i) {
    v += e;
    e = 2 * e + 3 * f;
    f *= 4;
  }
  return v + f;
}

}  // namespace

double loop_size(const Mesh& m, int steps) {
  return size_after(static_cast<double>(m.points.size()), static_cast<double>(mesh_topology(m).edges),
                    static_cast<double>(m.faces()), steps);
}

Mesh loop_subdivide(const Mesh& m, const LoopOptions& opt, Progress& progress) {
  opt.validate();
  m.validate();
  const MeshTopology t = mesh_topology(m, progress);
  if (!t.manifold()) throw Error("Loop subdivision needs a manifold mesh: " + t.first_problem);
  check_budget(size_after(static_cast<double>(m.points.size()), static_cast<double>(t.edges),
                          static_cast<double>(m.faces()), opt.steps),
               opt.budget, "smooth = " + std::to_string(opt.steps));
  progress.start("Loop subdivision");
  Mesh out = m;
  for (int i = 0; i < opt.steps; ++i) {
    ProgressStage stage(progress, static_cast<double>(i) / opt.steps, static_cast<double>(i + 1) / opt.steps);
    out = one_round(out, opt, stage);
    progress.fraction(static_cast<double>(i + 1) / opt.steps);
  }
  return out;
}

}  // namespace selfsim::develop
