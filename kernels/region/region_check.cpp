#include "kernels/region/region_check.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "kernels/base/cancellable_sort.h"
#include "kernels/base/check.h"
#include "kernels/base/error.h"
#include "kernels/geom/bbox.h"

namespace selfsim::region_detail {

namespace {

void two_sum(double a, double b, double& s, double& e) {
  s = a + b;
  const double bv = s - a, av = s - bv;
  e = (a - av) + (b - bv);
}

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

}  // namespace

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

std::string Rings::point(Index v) const {
  return "point " + std::to_string(source[v] - curve->path_begin(path[v]) + 1) + " " + coordinates(pts[v]);
}

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

}  // namespace selfsim::region_detail
