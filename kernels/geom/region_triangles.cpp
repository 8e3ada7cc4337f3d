#include "kernels/geom/region_triangles.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numeric>
#include <set>
#include <string>
#include <utility>

#include "kernels/geom/bbox.h"
#include "kernels/geom/cancellable_sort.h"
#include "kernels/geom/check.h"
#include "kernels/geom/error.h"

namespace selfsim {

namespace {

using Index = std::uint32_t;
using Tri = std::array<Index, 3>;
constexpr Index none = 0xffffffffu;

// ---- Exact orientation: the sweep's order of edges and the pieces' ear tests must never contradict each
// other, or the tree of edges and the faces fall apart on collinear input (a comb's teeth, a staircase).

void two_sum(double a, double b, double& s, double& e) {
  s = a + b;
  const double bv = s - a, av = s - bv;
  e = (a - av) + (b - bv);
}

// The sign of the turn a → b → c: 1 left (counter-clockwise), -1 right, 0 on one line, exactly. The
// floating-point determinant decides when it is beyond its error bound (Shewchuk's ccwerrboundA); else the
// six products of coordinates it expands to are summed exactly (each split into two doubles with fma) as a
// non-overlapping expansion, whose largest component has the sign.
int orientation(Vec2 a, Vec2 b, Vec2 c) {
  const double l = (b.x - a.x) * (c.y - a.y), r = (b.y - a.y) * (c.x - a.x), det = l - r;
  const double bound = 3.3306690738754716e-16 * (std::abs(l) + std::abs(r));
  if (det > bound) return 1;
  if (det < -bound) return -1;
  const double factors[6][2] = {{b.x, c.y}, {-b.x, a.y}, {-a.x, c.y}, {-b.y, c.x}, {a.x, b.y}, {a.y, c.x}};
  double e[12];
  int n = 0;
  auto grow = [&](double q) {  // Shewchuk's Grow-Expansion with zero elimination, in place
    int m = 0;
    for (int i = 0; i < n; ++i) {
      double s, err;
      two_sum(q, e[i], s, err);
      q = s;
      if (err != 0) e[m++] = err;
    }
    if (q != 0) e[m++] = q;
    n = m;
  };
  for (const auto& f : factors) {
    const double p = f[0] * f[1];
    grow(std::fma(f[0], f[1], -p));
    grow(p);
  }
  return n == 0 ? 0 : (e[n - 1] > 0 ? 1 : -1);
}

// The sweep's order: by y, ties by x (as if the sweep line were turned by an infinitesimal angle).
bool before(Vec2 a, Vec2 b) { return a.y < b.y || (a.y == b.y && a.x < b.x); }

std::string coordinates(Vec2 p) { return "(" + number_text(p.x) + ", " + number_text(p.y) + ")"; }

// Whether segments a-b and c-d share a point (crossing, touching or overlapping), exactly.
bool segments_touch(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const int d1 = orientation(a, b, c), d2 = orientation(a, b, d), d3 = orientation(c, d, a), d4 = orientation(c, d, b);
  if (d1 * d2 < 0 && d3 * d4 < 0) return true;
  auto on = [](Vec2 p, Vec2 q, Vec2 r) {  // r, on the line p-q, lies within the segment
    return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= r.y &&
           r.y <= std::max(p.y, q.y);
  };
  return (d1 == 0 && on(a, b, c)) || (d2 == 0 && on(a, b, d)) || (d3 == 0 && on(c, d, a)) || (d4 == 0 && on(c, d, b));
}

// The input's paths as rings of vertices: succ/pred in the input's order, before any turning around.
struct Rings {
  const Polyline* curve = nullptr;
  std::vector<Vec2> pts;
  std::vector<Index> source, path, succ, pred;

  // "point 3 (0.5, 1)": the vertex's point in its input path, counted from 1.
  std::string point(Index v) const {
    return "point " + std::to_string(source[v] - curve->path_begin(path[v]) + 1) + " " + coordinates(pts[v]);
  }
};

Rings prepare(const Polyline& c, const std::string& what, Progress& progress) {
  if (c.paths() == 0) throw Error(what + " needs at least one closed curve");
  if (c.points.size() >= none) throw Error(what + " of 4294967295 points or more is not supported");
  Rings r;
  r.curve = &c;
  r.pts.reserve(c.points.size());
  r.source.reserve(c.points.size());
  for (std::size_t p = 0; p < c.paths(); ++p) {
    const auto span = c.path(p);
    const std::string name = "path " + std::to_string(p + 1);
    for (std::size_t k = 0; k < span.size(); ++k)
      if (!is_finite(span[k]))
        throw Error(what + " needs finite points: point " + std::to_string(k + 1) + " of " + name + " is " +
                    coordinates(span[k]));
    if (span.size() < 3)
      throw Error(what + " needs paths of at least 3 distinct points: " + name + " has " + std::to_string(span.size()) +
                  " points");
    if (!closed_path(span))
      throw Error(what + " needs closed curves: " + name + " is open (it ends at " + coordinates(span.back()) +
                  ", not at its start)");
    const Index start = static_cast<Index>(r.pts.size());
    for (std::size_t k = 0; k + 1 < span.size(); ++k) {  // the closing repeat of the start dropped
      if (r.pts.size() > start && r.pts.back() == span[k]) continue;
      r.pts.push_back(span[k]);
      r.source.push_back(static_cast<Index>(c.path_begin(p) + k));
    }
    while (r.pts.size() > start + 1u && r.pts.back() == r.pts[start]) {
      r.pts.pop_back();
      r.source.pop_back();
    }
    const Index end = static_cast<Index>(r.pts.size());
    if (end - start < 3)
      throw Error(what + " needs paths of at least 3 distinct points: " + name + " has " + std::to_string(end - start) +
                  " distinct points");
    // All on one line (exactly): no area. A bowtie's lobes may cancel to none, but it is refused as crossing.
    bool flat = true;
    for (Index v = start + 2; v < end && flat; ++v) flat = orientation(r.pts[start], r.pts[start + 1], r.pts[v]) == 0;
    if (flat)
      throw Error(what + " needs curves that enclose an area: " + name + " encloses none (its points lie on one line)");
    for (Index v = start; v < end; ++v) {
      r.path.push_back(static_cast<Index>(p));
      r.succ.push_back(v + 1 == end ? start : v + 1);
      r.pred.push_back(v == start ? end - 1 : v - 1);
    }
    if ((p & 0xffff) == 0xffff) progress.step(0.05 * static_cast<double>(end) / static_cast<double>(c.points.size()));
  }
  return r;
}

// Refuses paths that cross or touch themselves or each other: each segment (vertex v to succ[v]) is listed in
// the cells of a uniform grid it passes through (cells of about twice the median segment, at most ~4 per
// segment), and the segments sharing a cell are tested pairwise. Neighbouring segments of a path always
// share their common point; they are at fault only when they fold back over each other.
void check_apart(const Rings& r, const std::string& what, Progress& progress) {
  const std::size_t n = r.pts.size();
  const auto& p = r.pts;
  BBox2 box;
  std::vector<double> lengths(n);
  for (std::size_t v = 0; v < n; ++v) {
    box.add(p[v]);
    lengths[v] = norm(p[r.succ[v]] - p[v]);
  }
  const Vec2 size = box.size();
  if (!(std::isfinite(size.x) && std::isfinite(size.y)))
    throw Error(what + ": the curves' extent overflows (coordinates up to about 1e300 in size are supported)");
  std::nth_element(lengths.begin(), lengths.begin() + static_cast<std::ptrdiff_t>(n / 2), lengths.end());
  double cell = std::max(2 * lengths[n / 2], 1e-12 * std::max(size.x, size.y));
  const double most = std::min(4.0 * static_cast<double>(n) + 64, 16777216.0);
  while ((size.x / cell + 1) * (size.y / cell + 1) > most) cell *= 1.5;
  const auto nx = static_cast<std::uint64_t>(size.x / cell) + 1, ny = static_cast<std::uint64_t>(size.y / cell) + 1;
  auto column = [&](double x) {
    return static_cast<std::uint64_t>(std::clamp(std::floor((x - box.min.x) / cell), 0.0, nx - 1.0));
  };
  auto row = [&](double y) {
    return static_cast<std::uint64_t>(std::clamp(std::floor((y - box.min.y) / cell), 0.0, ny - 1.0));
  };
  std::vector<std::uint64_t> entries;  // cell << 32 | segment
  entries.reserve(3 * n);
  for (Index s = 0; s < n; ++s) {
    Vec2 a = p[s], b = p[r.succ[s]];
    if (a.x > b.x) std::swap(a, b);
    const std::uint64_t i0 = column(a.x), i1 = column(b.x);
    // Column by column, the rows between the segment's lowest and highest y there, widened by far more than a
    // rounding so that a cell it only grazes is listed too.
    const double slope = b.x > a.x ? (b.y - a.y) / (b.x - a.x) : 0;
    const double pad = 1e-9 * cell * (1 + std::abs(slope));
    for (std::uint64_t i = i0; i <= i1; ++i) {
      const double x0 = i == i0 ? a.x : box.min.x + static_cast<double>(i) * cell;
      const double x1 = i == i1 ? b.x : box.min.x + static_cast<double>(i + 1) * cell;
      const double y0 = i == i0 ? a.y : a.y + slope * (x0 - a.x), y1 = i == i1 ? b.y : a.y + slope * (x1 - a.x);
      for (std::uint64_t j = row(std::min(y0, y1) - pad), hi = row(std::max(y0, y1) + pad); j <= hi; ++j)
        entries.push_back((j * nx + i) << 32 | s);
    }
  }
  cancellable_sort(entries.begin(), entries.end(), std::less<>(), progress);
  auto meet = [&](Index s, Index t) {
    const Index s1 = r.succ[s], t1 = r.succ[t];
    if (s1 == t || t1 == s) {  // neighbours along one path: at fault when they fold back over each other
      const Index shared = s1 == t ? t : s, a = s1 == t ? s : t, b = s1 == t ? t1 : s1;
      return orientation(p[shared], p[a], p[b]) == 0 && dot(p[a] - p[shared], p[b] - p[shared]) > 0;
    }
    return segments_touch(p[s], p[s1], p[t], p[t1]);
  };
  std::pair<Index, Index> bad{none, none};
  std::size_t work = 0;
  for (std::size_t begin = 0, end = 0; begin < entries.size(); begin = end) {
    for (end = begin; end < entries.size() && entries[end] >> 32 == entries[begin] >> 32;) ++end;
    for (std::size_t i = begin; i < end; ++i)
      for (std::size_t j = i + 1; j < end; ++j) {
        if ((++work & 0xffff) == 0) progress.step(0.05 + 0.3 * static_cast<double>(begin) / entries.size());
        const auto s = static_cast<Index>(entries[i]), t = static_cast<Index>(entries[j]);
        if (std::pair(s, t) < bad && meet(s, t)) bad = {s, t};
      }
  }
  if (bad.first == none) return;
  const auto [s, t] = bad;
  if (r.path[s] == r.path[t])
    throw Error(what + " needs simple curves: path " + std::to_string(r.path[s] + 1) +
                " crosses or touches itself where its segments from " + r.point(s) + " and from " + r.point(t) +
                " meet");
  throw Error(what + " needs curves apart: paths " + std::to_string(r.path[s] + 1) + " and " +
              std::to_string(r.path[t] + 1) + " cross or touch where the segment from " + r.point(s) + " of path " +
              std::to_string(r.path[s] + 1) + " meets the segment from " + r.point(t) + " of path " +
              std::to_string(r.path[t] + 1));
}

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

}  // namespace

RegionTriangles region_triangles(const Polyline& c, Progress& progress, std::string_view what) {
  const std::string name(what);
  Rings rings = prepare(c, name, progress);
  check_apart(rings, name, progress);
  std::vector<std::pair<Index, Index>> diagonals;
  RegionTriangles out;
  out.next = sweep(rings, diagonals, progress);
  triangulate_pieces(rings, out.next, diagonals, out.triangles, progress);
  progress.fraction(1);
  out.points = std::move(rings.pts);
  out.source = std::move(rings.source);
  out.path_of_point = std::move(rings.path);
  return out;
}

}  // namespace selfsim
