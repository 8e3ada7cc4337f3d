// The obstacles of Bowyer's original rule (original_split.h) in a uniform grid, and the walk along a
// split's bisector that visits every obstacle able to set its limits, so that the grid gives exactly the
// brute-force answer of his program (every split against every vertex and segment) without its O(N²).
//
// Why nothing it leaves out can change the result (frame: t along N0 from M, x across it; u the unit
// roundoff, "size" the grid's largest coordinate or extent, about 1 in the run's coordinates):
//
// 1. Segments. A segment's candidate T ∓ r/S can be far below its crossing T (S, the sine of its angle to
//    the bisector, has no useful lower bound), so no crossing is too far away to matter: each side walks
//    its half of the bisector line to the edge of the grid and visits every cell within `pad` of it. A
//    segment the test accepts (computed s in [0, 1]) comes within a few roundings of the line (its ends'
//    signed distances have opposite signs up to rounding), and it is listed in every cell it passes
//    through, widened by the same pad, so the walk meets it in the cell where it meets the line. Its
//    candidate goes to the side of its computed crossing T, whose numerator (a cross product over |d|) is
//    good to a few roundings of size²/|d| and whose denominator is the sine |d·N1|/|d|: T is within
//    noise/|d·N1| (noise ≈ 90u·size²) of the true crossing. The test needs |d·N1| ≥ ε, so each side's
//    walk starts noise/ε behind M, on the other side.
// 2. Vertices. Only points less than h + r from the bisector are tested (the band): each side visits the
//    cells within w ≥ h + r (plus rounding) of its half line, out to a reach Y. A tangent from E = (h, 0)
//    to the disc of radius r around p = (x, y), 0 < x < h + r, crossing the bisector at T satisfies
//    h·y ≤ T·(h − x) + r·sqrt(T² + h²) (the line's distance from p is r). A candidate that can still
//    lower the side's limit c has −ε < T < c, so h·y ≤ c·h + ε·r + r·sqrt(max(c, ε)² + h²): every point
//    beyond Y(c) = c + (ε·r + r·sqrt(max(c, ε)² + h²)) / h is useless. Y is taken with c, ε and r
//    enlarged far beyond the rounding of a computed tangent and of its crossing, and the limit only falls
//    as the walk goes out, so Y only shrinks: once a strip lies beyond it, all the later ones do. A
//    vertex's side (the sign of N0·p + c0) is good to a few roundings of size²/h, so each side also
//    starts that far behind M, and leaves the points clearly behind it to the other side.
// 3. Order. Each side's final limit is the extreme of its candidates, so visiting a cell twice, or a
//    candidate of the other side, changes nothing. The positive side walks first, to the end, so T⁺ is
//    exact; then the negative side stops as soon as |T⁻| ≤ T⁺ (T⁻ only rises toward 0 as it walks, so
//    the positive side is chosen whatever the rest would give; when T⁺ = 0 this waits for T⁻ = 0, so a
//    stuck split is exact too).
// 4. Directions. A crossing at t ahead of the limit c, of a segment at sine S ≥ 1e-4, gives at least
//    t − (r·(1 + 1e-5) + 2·noise/L)/S (L the shortest segment): only sines below
//    (r·(1 + 1e-5) + 2·noise/L)/(t − c) can lower c. Behind M, only crossings whose rounding can bring
//    them to this side: sines below 2·noise/(L·|t|). Each cell keeps the bins (π/64 wide) of its
//    segments' directions; a strip skips the cells with none in the window of sines still possible
//    (never narrower than 1e-4, widened by 1e-3 radians for the rounding of angles). The same bounds skip
//    single segments (original_walk.cpp).
// 5. Cells. A point's cell is floor((x − origin)·(1/cell)), monotone in x, so a walk whose computed range
//    contains a point's coordinate visits that point's cell; `pad` is far above the rounding of every
//    computed position. Obstacles outside the grid's bounds (a point made during a level beyond the
//    bounds taken at its start) are not in cells; the caller tests them on every split.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

#include "kernels/geom/bbox.h"
#include "kernels/geom/vec2.h"

namespace selfsim::exclusion::original {

// A listed obstacle, with its position(s), so that a walk reads cells without looking elsewhere.
struct VertexEntry {
  Vec2 at;
  std::uint32_t id;
};
struct SegmentEntry {
  Vec2 from, to;
  std::uint32_t id;
};

class ObstacleGrid {
 public:
  // An empty grid of square cells of side `cell` over `bounds`; larger cells when that would make more
  // than 2^22 of them.
  void reset(const BBox2& bounds, double cell);
  // Whether p lies within the bounds, so that it may be listed.
  bool covers(Vec2 p) const {
    return p.x >= bounds_.min.x && p.x <= bounds_.max.x && p.y >= bounds_.min.y && p.y <= bounds_.max.y;
  }
  // Lists a vertex or a segment (its points covered) under an id.
  void add_vertex(std::uint32_t id, Vec2 p);
  void add_segment(std::uint32_t id, Vec2 p, Vec2 q);
  // Packs what is listed so far cell by cell, dropping the segments whose alive[id] is 0: walks read packed
  // cells faster. Worth it after a level's first listing, and whenever much has been added since.
  void pack(const std::vector<std::uint8_t>& alive);
  std::size_t packed() const { return segments_.items.size() + vertices_.items.size(); }
  std::size_t added() const { return segments_.extra.size() + vertices_.extra.size(); }
  // Rounding allowance for positions: far more than a few roundings of the grid's largest coordinate.
  double pad() const { return pad_; }
  // Directions of segments, modulo π, in 64 bins of π/64: a cell knows which bins its segments fall in.
  using Bins = std::uint64_t;
  static double direction(Vec2 d) {
    const double a = std::atan2(d.y, d.x);
    return a < 0 ? a + std::numbers::pi : a;
  }
  // The bins of the directions within `half_width` of `angle` (modulo π).
  static Bins direction_bins(double angle, double half_width);
  double cell() const { return cell_; }

  // Walks the half line m + u·t (u a unit vector), strip by strip away from m: t ≥ −behind for segments,
  // t ≥ −side for vertices. For each strip
  // while !w.finished(): w.segments(list) for the cells within pad() of the half line that list a segment
  // whose direction is among w.directions(lo, hi, angle) (a set of direction_bins() for crossings at t in
  // [lo, hi], the half line's direction being `angle`), then, until a strip
  // lies beyond w.reach() in t, w.vertices(list, reach) for the cells within `width` of its part
  // t ≤ reach.
  // A list calls list.each(f) with each of its entries.
  template <class Walker>
  void walk(Vec2 m, Vec2 u, double behind, double side, double width, Walker& w) const;

 private:
  template <class Entry>
  struct Cells {
    std::vector<std::uint32_t> begin;  // packed: cell c holds items[begin[c] .. begin[c + 1])
    std::vector<Entry> items;
    std::vector<std::uint32_t> head, next;  // added since: a linked list per cell through extra
    std::vector<Entry> extra;

    void clear(std::size_t cells);
    void add(std::size_t cell, const Entry& e);
    void pack(const std::uint8_t* alive);  // alive: null keeps every entry
  };
  // The entries listed in one cell.
  template <class Entry>
  struct List {
    const Cells<Entry>* c;
    std::size_t cell;
    template <class F>
    void each(F&& f) const {
      const Entry* e = c->items.data();
      for (std::uint32_t k = c->begin[cell], end = c->begin[cell + 1]; k < end; ++k) f(e[k]);
      for (std::uint32_t k = c->head[cell]; k != none_; k = c->next[k]) f(c->extra[k]);
    }
  };
  // The line m + u·t with coordinates along the walk's major axis (a) and the other (b).
  struct Axes {
    int major;
    double ma, mb, ua, ub, inverse;  // inverse: 1 / ua
  };
  static constexpr std::uint32_t none_ = std::numeric_limits<std::uint32_t>::max();

  static Axes axes(Vec2 m, Vec2 u);
  // The strip holding coordinate v along an axis, floor((v − origin)·(1/cell)) clamped to [-1, count]
  // (-1 and the count: beyond the grid), monotone in v.
  int index(double v, int axis) const {
    const double k = (v - origin(axis)) * inverse_cell_;
    if (!(k >= 0)) return -1;
    const int n = count(axis);
    return k < n ? static_cast<int>(k) : n;
  }
  int count(int axis) const { return axis == 0 ? nx_ : ny_; }
  double origin(int axis) const { return axis == 0 ? bounds_.min.x : bounds_.min.y; }
  std::size_t cell_at(const Axes& l, int k, int j) const {
    return l.major == 0 ? static_cast<std::size_t>(j) * nx_ + k : static_cast<std::size_t>(k) * nx_ + j;
  }
  // The cells of strip k (a column for major axis 0, else a row) that meet {m + u·t : t in [t0, t1]}
  // widened by `pad` along both axes, as the range [j0, j1] across the strip; false if none.
  // [lo, hi]: the range of t of the part within the strip.
  bool strip(const Axes& l, int k, double t0, double t1, double pad, int& j0, int& j1, double& lo, double& hi) const {
    const double a0 = origin(l.major) + k * cell_ - pad, a1 = origin(l.major) + (k + 1) * cell_ + pad;
    lo = (a0 - l.ma) * l.inverse;
    hi = (a1 - l.ma) * l.inverse;
    if (lo > hi) std::swap(lo, hi);
    lo = std::max(lo, t0);
    hi = std::min(hi, t1);
    if (!(lo <= hi)) return false;
    const double b0 = l.mb + l.ub * lo, b1 = l.mb + l.ub * hi;
    const int minor = 1 - l.major;
    j0 = std::max(index(std::min(b0, b1) - pad, minor), 0);
    j1 = std::min(index(std::max(b0, b1) + pad, minor), count(minor) - 1);
    return j0 <= j1;
  }
  // Calls f(cell) for the cells that {m + u·t : t in [t0, t1]} widened by pad() meets.
  template <class F>
  void cover(const Axes& l, double t0, double t1, F&& f) const;

  BBox2 bounds_;
  double cell_ = 0, inverse_cell_ = 0, pad_ = 0;
  int nx_ = 0, ny_ = 0;
  Cells<VertexEntry> vertices_;
  Cells<SegmentEntry> segments_;
  std::vector<Bins> directions_;  // per cell: the bins of its segments' directions (never cleared)
};

template <class F>
void ObstacleGrid::cover(const Axes& l, double t0, double t1, F&& f) const {
  const double a0 = l.ma + l.ua * t0, a1 = l.ma + l.ua * t1;
  const int k0 = std::max(index(std::min(a0, a1) - pad_, l.major), 0);
  const int k1 = std::min(index(std::max(a0, a1) + pad_, l.major), count(l.major) - 1);
  for (int k = k0; k <= k1; ++k) {
    int j0, j1;
    double lo, hi;
    if (!strip(l, k, t0, t1, pad_, j0, j1, lo, hi)) continue;
    for (int j = j0; j <= j1; ++j) f(cell_at(l, k, j));
  }
}

template <class Walker>
void ObstacleGrid::walk(Vec2 m, Vec2 u, double behind, double side, double width, Walker& w) const {
  const Axes l = axes(m, u);
  const int step = l.ua > 0 ? 1 : -1, n = count(l.major);
  // From the strip holding the farthest point behind m that either part can reach.
  int k = index(l.ma - step * std::max(behind + pad_, side + width + pad_), l.major);
  k = std::clamp(k, 0, n - 1);
  bool vertices = true;
  const double far = std::numeric_limits<double>::infinity();
  const double angle = direction(u);
  for (; k >= 0 && k < n; k += step) {
    if (w.finished()) return;
    int j0, j1;
    double lo, hi;
    if (strip(l, k, -behind, far, pad_, j0, j1, lo, hi)) {
      const Bins bins = w.directions(lo, hi, angle);
      for (int j = j0; j <= j1; ++j) {
        const std::size_t cell = cell_at(l, k, j);
        if (directions_[cell] & bins) w.segments(List<SegmentEntry>{&segments_, cell});
      }
    }
    if (!vertices) continue;
    const double reach = w.reach();
    // The strip's nearest t for the widened part: beyond the reach, this strip and all later ones are done.
    const double edge = origin(l.major) + (step > 0 ? k * cell_ - width - pad_ : (k + 1) * cell_ + width + pad_);
    if ((edge - l.ma) * l.inverse > reach) {
      vertices = false;
      continue;
    }
    if (strip(l, k, -side, reach, width, j0, j1, lo, hi))
      for (int j = j0; j <= j1; ++j) w.vertices(List<VertexEntry>{&vertices_, cell_at(l, k, j)}, reach);
  }
}

}  // namespace selfsim::exclusion::original
