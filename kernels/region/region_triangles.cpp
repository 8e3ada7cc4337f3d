#include "kernels/region/region_triangles.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <numeric>
#include <set>
#include <string>
#include <utility>

#include "kernels/base/cancellable_sort.h"
#include "kernels/base/error.h"
#include "kernels/region/region_check.h"

namespace selfsim {

namespace {

using namespace region_detail;
using Tri = std::array<Index, 3>;

// The edges crossing the sweep line, left to right. Edge e joins vertex e and succ[e]; it is compared by
// the position of the later of two lower ends against the other edge (they cross no other edge, so this
// is their order all along the sweep line where both are).
struct EdgeOrder {
  using is_transparent = void;
  const Rings* r;

  Index low(Index e) const { return before(r->pts[e], r->pts[r->succ[e]]) ? e : r->succ[e]; }
  Index high(Index e) const { return before(r->pts[e], r->pts[r->succ[e]]) ? r->succ[e] : e; }
  bool operator()(Index a, Index b) const {
    const auto& p = r->pts;
    const Index a0 = low(a), b0 = low(b);
    if (a0 == b0) return orientation(p[a0], p[high(b)], p[high(a)]) > 0;
    if (before(p[b0], p[a0])) return orientation(p[b0], p[high(b)], p[a0]) > 0;
    return orientation(p[a0], p[high(a)], p[b0]) < 0;
  }
  // An edge against a point: the edge lies left of it, or it left of the edge.
  bool operator()(Index a, Vec2 q) const { return orientation(r->pts[low(a)], r->pts[high(a)], q) < 0; }
  bool operator()(Vec2 q, Index b) const { return orientation(r->pts[low(b)], r->pts[high(b)], q) > 0; }
};

// The sweep: orients every path by its nesting and lists the diagonals that cut the region into monotone
// pieces. Returns the oriented next vertex of every vertex.
std::vector<Index> sweep(const Rings& r, std::vector<std::pair<Index, Index>>& diagonals, Progress& progress) {
  const std::size_t n = r.pts.size();
  const auto& p = r.pts;
  std::vector<Index> order(n);
  std::iota(order.begin(), order.end(), Index{0});
  ProgressStage sorting(progress, 0.35, 0.45);
  cancellable_sort(
      order.begin(), order.end(), [&](Index a, Index b) { return before(p[a], p[b]); }, sorting);

  std::vector<char> started(r.curve->paths(), 0), flip(r.curve->paths(), 0), merge(n, 0);
  std::vector<Index> helper(n, none);
  auto next = [&](Index v) { return flip[r.path[v]] ? r.pred[v] : r.succ[v]; };
  auto prev = [&](Index v) { return flip[r.path[v]] ? r.succ[v] : r.pred[v]; };
  auto edge = [&](Index v, Index w) { return r.succ[v] == w ? v : w; };  // the edge joining neighbours v, w
  auto region_on_right = [&](Index e) {  // the region lies right of the edge: it runs downwards, oriented
    const bool f = flip[r.path[e]];
    return before(p[f ? e : r.succ[e]], p[f ? r.succ[e] : e]);
  };
  using Status = std::set<Index, EdgeOrder>;
  Status status(EdgeOrder{&r});
  std::vector<Status::iterator> where(n);
  auto broken = [&](Index v) {
    return Error("region triangles: the sweep lost its way at " + r.point(v) + " of path " +
                 std::to_string(r.path[v] + 1) + " (please report this curve)");
  };
  auto insert = [&](Index e, Index h) {
    const auto [it, fresh] = status.insert(e);
    if (!fresh) throw broken(h);
    where[e] = it;
    helper[e] = h;
  };
  auto left_of = [&](Index v) {  // the edge just left of v, whose helper v may connect to
    auto it = status.lower_bound(p[v]);
    if (it == status.begin()) throw broken(v);
    return *std::prev(it);
  };
  auto connect_merge = [&](Index v, Index e) {
    if (merge[helper[e]]) diagonals.push_back({v, helper[e]});
  };

  for (std::size_t k = 0; k < n; ++k) {
    if ((k & 0xffff) == 0xffff) progress.step(0.45 + 0.35 * static_cast<double>(k) / static_cast<double>(n));
    const Index v = order[k];
    if (!started[r.path[v]]) {
      // The path's lowest point: inside the region when the edge just left of it has the region on its right.
      // Turn the path so that the region lies on its left.
      started[r.path[v]] = 1;
      const auto it = status.lower_bound(p[v]);
      const bool inside = it != status.begin() && region_on_right(*std::prev(it));
      const bool counter_clockwise = orientation(p[r.pred[v]], p[v], p[r.succ[v]]) > 0;
      flip[r.path[v]] = counter_clockwise == inside;
    }
    const Index a = prev(v), b = next(v);
    const Index in = edge(a, v), out = edge(v, b);
    const bool a_above = before(p[v], p[a]), b_above = before(p[v], p[b]);
    const bool convex = orientation(p[a], p[v], p[b]) > 0;
    if (a_above && b_above) {
      if (!convex) {  // split: joined to the helper of the edge left of it
        const Index e = left_of(v);
        diagonals.push_back({v, helper[e]});
        helper[e] = v;
      }
      insert(in, v);  // start or split: the edge in (downwards) has the region on its right
      insert(out, v);
    } else if (!a_above && !b_above) {
      connect_merge(v, out);
      status.erase(where[in]);
      status.erase(where[out]);
      if (!convex) {  // merge
        merge[v] = 1;
        const Index e = left_of(v);
        connect_merge(v, e);
        helper[e] = v;
      }
    } else if (a_above) {  // regular, the region on its right
      connect_merge(v, out);
      status.erase(where[out]);
      insert(in, v);
    } else {  // regular, the region on its left
      status.erase(where[in]);
      const Index e = left_of(v);
      connect_merge(v, e);
      helper[e] = v;
      insert(out, v);
    }
  }
  std::vector<Index> oriented(n);
  for (Index v = 0; v < n; ++v) oriented[v] = next(v);
  return oriented;
}

// Triangulates one y-monotone piece (vertices counter-clockwise) by the stack method, appending
// face.size() - 2 counter-clockwise triangles.
void triangulate_monotone(const std::vector<Index>& face, const std::vector<Vec2>& p, std::vector<Tri>& out,
                          std::vector<std::pair<Index, bool>>& sorted, std::vector<std::pair<Index, bool>>& stack) {
  const std::size_t m = face.size();
  std::size_t lo = 0, hi = 0;
  for (std::size_t k = 1; k < m; ++k) {
    if (before(p[face[k]], p[face[lo]])) lo = k;
    if (before(p[face[hi]], p[face[k]])) hi = k;
  }
  // Merged in sweep order: forward from the lowest vertex is the right chain, backward the left.
  sorted.clear();
  sorted.push_back({face[lo], false});
  for (std::size_t i = (lo + 1) % m, j = (lo + m - 1) % m; i != hi || j != hi;) {
    if (j == hi || (i != hi && before(p[face[i]], p[face[j]]))) {
      sorted.push_back({face[i], true});
      i = (i + 1) % m;
    } else {
      sorted.push_back({face[j], false});
      j = (j + m - 1) % m;
    }
  }
  sorted.push_back({face[hi], false});  // its chain, the one opposite the stack's top, is settled below
  // Triangle of a pair of stack vertices (lower, upper) of one chain and a vertex u of the other.
  auto fan = [&](Index lower, Index upper, Index u, bool u_right) {
    out.push_back(u_right ? Tri{lower, u, upper} : Tri{lower, upper, u});
  };
  stack.assign({sorted[0], sorted[1]});
  for (std::size_t k = 2; k + 1 < m; ++k) {
    const auto [u, right] = sorted[k];
    if (right != stack.back().second) {
      for (std::size_t s = 0; s + 1 < stack.size(); ++s) fan(stack[s].first, stack[s + 1].first, u, right);
      const auto top = stack.back();
      stack.assign({top, sorted[k]});
    } else {
      auto last = stack.back();
      stack.pop_back();
      while (!stack.empty()) {
        const Index t = stack.back().first;
        const Tri tri = right ? Tri{t, last.first, u} : Tri{t, u, last.first};
        if (orientation(p[tri[0]], p[tri[1]], p[tri[2]]) <= 0) break;
        out.push_back(tri);
        last = stack.back();
        stack.pop_back();
      }
      stack.push_back(last);
      stack.push_back(sorted[k]);
    }
  }
  const Index top = sorted[m - 1].first;
  const bool top_right = !stack.back().second;
  for (std::size_t s = 0; s + 1 < stack.size(); ++s) fan(stack[s].first, stack[s + 1].first, top, top_right);
}

// Walks the pieces the boundary and the diagonals cut the region into, and triangulates each.
void triangulate_pieces(const Rings& r, const std::vector<Index>& next,
                        const std::vector<std::pair<Index, Index>>& diagonals, std::vector<Tri>& out,
                        Progress& progress) {
  const std::size_t n = r.pts.size();
  const auto& p = r.pts;
  // Half-edges out of each vertex: the boundary edge to next, and each diagonal both ways.
  std::vector<std::size_t> first(n + 1, 0);
  for (Index v = 0; v < n; ++v) first[v + 1] = 1;
  for (const auto& [a, b] : diagonals) ++first[a + 1], ++first[b + 1];
  for (std::size_t v = 0; v < n; ++v) first[v + 1] += first[v];
  std::vector<Index> target(first[n]), owner(first[n]);
  std::vector<std::size_t> fill(first.begin(), first.end() - 1);
  auto add = [&](Index a, Index b) {
    owner[fill[a]] = a;
    target[fill[a]++] = b;
  };
  for (Index v = 0; v < n; ++v) add(v, next[v]);
  for (const auto& [a, b] : diagonals) add(a, b), add(b, a);
  // After arriving at w from u, the piece on the left goes on along the half-edge out of w that comes first
  // clockwise from the direction back to u.
  auto after = [&](std::size_t h) {
    const Index u = owner[h], w = target[h];
    auto turn = [&](Index t) {  // 0: within a half turn clockwise, 1: straight back, 2: beyond, 3: along u
      const int o = orientation(p[w], p[u], p[t]);
      return o < 0 ? 0 : o > 0 ? 2 : dot(p[u] - p[w], p[t] - p[w]) < 0 ? 1 : 3;
    };
    std::size_t best = first[w];
    for (std::size_t k = first[w] + 1; k < first[w + 1]; ++k) {
      const int tk = turn(target[k]), tb = turn(target[best]);
      if (tk < tb || (tk == tb && (tk == 0 || tk == 2) && orientation(p[w], p[target[k]], p[target[best]]) < 0))
        best = k;
    }
    return best;
  };
  std::vector<char> used(first[n], 0);
  std::vector<Index> face;
  std::vector<std::pair<Index, bool>> sorted, stack;
  out.reserve(n + 2 * diagonals.size());
  for (std::size_t h0 = 0, walked = 0; h0 < first[n]; ++h0) {
    if (used[h0]) continue;
    face.clear();
    std::size_t h = h0;
    do {
      if (used[h] || face.size() > n) throw Error("region triangles: a piece of the region does not close");
      used[h] = 1;
      face.push_back(owner[h]);
      h = after(h);
      if ((++walked & 0xffff) == 0) progress.step(0.8 + 0.2 * static_cast<double>(walked) / first[n]);
    } while (h != h0);
    if (face.size() < 3) throw Error("region triangles: a piece of the region has fewer than 3 corners");
    triangulate_monotone(face, p, out, sorted, stack);
  }
}

// ---- Slivers. Points on one line only to a rounding (a Koch snowflake's sides, made by rotations and
// thirds) are, exactly, a hair off it, so the stack method may cut off a triangle of three of them that is
// rightly counter-clockwise but a rounding error high: a relief's cap then touches its own walls. Each such
// sliver whose long side is a diagonal is flipped away, the exact turn tests keeping every triangle
// counter-clockwise.

// A triangle's height over its longest side (twice its area over that side squared), scale-free and the
// same whichever corner it is read from (the smallest index first), so that flips can only improve it.
double shape(const std::vector<Vec2>& p, Tri t) {
  const int k = t[0] < t[1] ? (t[0] < t[2] ? 0 : 2) : (t[1] < t[2] ? 1 : 2);
  const Vec2 a = p[t[k]], b = p[t[(k + 1) % 3]], c = p[t[(k + 2) % 3]];
  Vec2 u = b - a, v = c - a, w = c - b;
  const double s = std::max({std::abs(u.x), std::abs(u.y), std::abs(v.x), std::abs(v.y), std::abs(w.x), std::abs(w.y)});
  if (!(s > 0)) return 0;
  u = u * (1 / s), v = v * (1 / s), w = w * (1 / s);
  return cross(u, v) / std::max({dot(u, u), dot(v, v), dot(w, w)});
}

// Flips diagonals of triangles flatter than a millionth (height over longest side) while the flip leaves
// both triangles of the pair less flat than the flatter was: each flip raises the sorted list of all
// triangles' shapes, so the flips end, and O(1) each; nothing is done (not even the neighbours' table)
// when no triangle is that flat.
void flip_slivers(const std::vector<Vec2>& p, std::vector<Tri>& tris) {
  constexpr double flat = 1e-6;
  std::vector<Index> work;
  for (Index t = 0; t < tris.size(); ++t)
    if (shape(p, tris[t]) < flat) work.push_back(t);
  if (work.empty()) return;
  // Half-edge 3t + k runs from corner k to corner k + 1 of triangle t; twin[h]: the same edge in the
  // neighbouring triangle, or none on the boundary.
  const std::size_t halves = 3 * tris.size();
  std::vector<std::pair<std::uint64_t, std::size_t>> keys(halves);
  for (std::size_t h = 0; h < halves; ++h) {
    const Index a = tris[h / 3][h % 3], b = tris[h / 3][(h + 1) % 3];
    keys[h] = {std::uint64_t{std::min(a, b)} << 32 | std::max(a, b), h};
  }
  std::sort(keys.begin(), keys.end());
  std::vector<std::size_t> twin(halves, SIZE_MAX);
  for (std::size_t i = 0; i + 1 < keys.size(); ++i)
    if (keys[i].first == keys[i + 1].first)
      twin[keys[i].second] = keys[i + 1].second, twin[keys[i + 1].second] = keys[i].second;
  auto link = [&](std::size_t h, std::size_t g) {
    twin[h] = g;
    if (g != SIZE_MAX) twin[g] = h;
  };
  while (!work.empty()) {
    const Index t = work.back();
    work.pop_back();
    const double before_t = shape(p, tris[t]);
    if (before_t >= flat) continue;
    // The best flip of one of t's three sides: t = (a, b, c) and u = (b, a, d) become (c, a, d), (d, b, c).
    std::size_t best = SIZE_MAX;
    double best_shape = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      const std::size_t g = twin[3 * t + k];
      if (g == SIZE_MAX) continue;
      const Tri& u = tris[g / 3];
      const Index a = tris[t][k], b = tris[t][(k + 1) % 3], c = tris[t][(k + 2) % 3], d = u[(g % 3 + 2) % 3];
      if (orientation(p[a], p[d], p[c]) <= 0 || orientation(p[d], p[b], p[c]) <= 0) continue;
      const double now = std::min(before_t, shape(p, u));
      const double then = std::min(shape(p, {c, a, d}), shape(p, {d, b, c}));
      if (then > now && then > best_shape) best = 3 * t + k, best_shape = then;
    }
    if (best == SIZE_MAX) continue;
    const std::size_t k = best % 3, g = twin[best], j = g % 3;
    const Index ut = static_cast<Index>(g / 3);
    const Index a = tris[t][k], b = tris[t][(k + 1) % 3], c = tris[t][(k + 2) % 3], d = tris[ut][(j + 2) % 3];
    const std::size_t bc = twin[3 * t + (k + 1) % 3], ca = twin[3 * t + (k + 2) % 3];
    const std::size_t ad = twin[3 * ut + (j + 1) % 3], db = twin[3 * ut + (j + 2) % 3];
    tris[t] = {c, a, d};
    tris[ut] = {d, b, c};
    link(3 * t, ca), link(3 * t + 1, ad), link(3 * t + 2, 3 * ut + 2);
    link(3 * ut, db), link(3 * ut + 1, bc);
    // The pair and their neighbours may now have (better) flips.
    work.push_back(t);
    work.push_back(ut);
    for (const std::size_t e : {bc, ca, ad, db})
      if (e != SIZE_MAX) work.push_back(static_cast<Index>(e / 3));
  }
}

}  // namespace

RegionTriangles region_triangles(const Polyline& c, Progress& progress, std::string_view what) {
  const std::string name(what);
  Rings rings = prepare(c, name, progress);
  check_apart(rings, name, progress);
  std::vector<std::pair<Index, Index>> diagonals;
  RegionTriangles out;
  out.next = sweep(rings, diagonals, progress);
  triangulate_pieces(rings, out.next, diagonals, out.triangles, progress);
  flip_slivers(rings.pts, out.triangles);
  progress.fraction(1);
  out.points = std::move(rings.pts);
  out.source = std::move(rings.source);
  out.path_of_point = std::move(rings.path);
  return out;
}

}  // namespace selfsim
