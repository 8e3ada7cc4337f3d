#include "kernels/exclusion/curve_net.h"

#include <algorithm>
#include <cmath>

#include "kernels/exclusion/chain_order.h"
#include "kernels/exclusion/start_check.h"

namespace selfsim::exclusion {

namespace {

// Whether segment s is farther than r from the quadrilateral a, p(positive), b, p(-negative), which holds
// both new segments for every move still allowed: then it cannot narrow the limits. In the split's frame
// (along e, along n) the quadrilateral is the diamond |s|/h + t/positive <= 1 (t >= 0) and its mirror.
bool apart(const SplitFrame& f, const Segment& s, double positive, double negative, double r) {
  const Vec2 u = s.u - f.m, v = s.v - f.m;
  const double su = dot(u, f.e), sv = dot(v, f.e), tu = dot(u, f.n), tv = dot(v, f.n);
  if ((su > f.h + r && sv > f.h + r) || (su < -f.h - r && sv < -f.h - r)) return true;
  if ((tu > positive + r && tv > positive + r) || (tu < -negative - r && tv < -negative - r)) return true;
  // Beyond one of the diamond's four edges by more than r: the edge from (±h, 0) to (0, ±height) has
  // outward normal (height, h) up to signs; compared squared, so without a square root.
  for (int side = 0; side < 4; ++side) {
    const double sx = side & 1 ? -1 : 1, height = side & 2 ? negative : positive, sy = side & 2 ? -1 : 1;
    const double limit = r * r * (height * height + f.h * f.h);
    auto beyond = [&](double s0, double t0) {
      const double d = height * sx * s0 + f.h * sy * t0 - f.h * height;
      return d > 0 && d * d > limit;
    };
    if (beyond(su, tu) && beyond(sv, tv)) return true;
  }
  return false;
}

}  // namespace

Curves::Curves(const Region& region, const Polyline& start, const CurveOptions& opt, double points)
    : region_(region), opt_(opt), far_(2 * norm(region.bbox().size())) {
  at_.reserve(static_cast<std::size_t>(points));
  next_.reserve(at_.capacity());
  prev_.reserve(at_.capacity());
  out_.reserve(at_.capacity());
  level_.reserve(at_.capacity());
  // Room for the most segments listed at once (breadth first: a level's and two for each split, 1.5 a
  // point; depth first: two for each split, 2 a point), reserved once so that every level reuses the same
  // memory instead of touching fresh pages (page faults were a tenth of a 2^20-segment run).
  segments_.reserve(region.edges() + 2 * at_.capacity());
  for (std::size_t i = 0; i < start.paths(); ++i) {
    const auto p = start.path(i);
    const bool loop = exact_loop(p);
    const std::size_t n = loop ? p.size() - 1 : p.size();
    const auto first = static_cast<std::uint32_t>(at_.size());
    for (std::size_t k = 0; k < n; ++k) {
      at_.push_back(p[k]);
      next_.push_back(k + 1 < n ? first + static_cast<std::uint32_t>(k + 1) : loop ? first : none);
      prev_.push_back(k > 0  ? first + static_cast<std::uint32_t>(k - 1)
                      : loop ? first + static_cast<std::uint32_t>(n - 1)
                             : none);
      out_.push_back(none);
      level_.push_back(0);
    }
    first_.push_back(first);
    closed_.push_back(loop);
  }
}

std::uint32_t Curves::add(Vec2 u, Vec2 v, std::uint32_t from, std::uint32_t to) {
  const auto id = static_cast<std::uint32_t>(segments_.size());
  segments_.push_back({u, v, from, to});
  if (!opt_.brute_force) grid_.insert(id, u, v);
  return id;
}

void Curves::renumber() {
  std::vector<std::uint32_t> order;  // old numbers, in their new order
  order.reserve(at_.size());
  append_chains(order, first_, next_, none);
  permute(at_, order);
  permute(next_, order);
  permute(prev_, order);
  permute(level_, order);
  relink(next_, order, none);
  relink(prev_, order, none);
}

void Curves::index(double cell) {
  // Vertices numbered along their curves, so that a level's splits, taken in that order, find their
  // vertices and segments near each other in memory.
  renumber();
  segments_.clear();
  grid_ = SegmentGrid(region_.bbox(), cell);
  query_ = 0;
  for (std::size_t e = 0; e < region_.edges(); ++e) add(region_.edge_start(e), region_.edge_end(e));
  for (std::uint32_t v = 0; v < at_.size(); ++v)
    out_[v] = next_[v] == none ? none : add(at_[v], at_[next_[v]], v, next_[v]);
  vertex_seen_.assign(at_.size(), 0);
}

double Curves::mean_length() const {
  double length = 0, count = 0;
  for (std::uint32_t v = 0; v < at_.size(); ++v)
    if (next_[v] != none) length += norm(at_[next_[v]] - at_[v]), ++count;
  return count > 0 ? length / count : 0;
}

bool Curves::first_visit(std::uint32_t x) {
  if (x == none) return true;
  if (vertex_seen_[x] == query_) return false;
  vertex_seen_[x] = query_;
  return true;
}

void Curves::limit(const SplitFrame& f, std::uint32_t id, std::uint32_t self, double r, Reach& limits) {
  const Segment& s = segments_[id];
  if (!s.alive || id == self) return;
  if (opt_.exclusion == Mode::vertex) {
    limit_vertex(f, s.u, s.v, r, limits);
    return;
  }
  // Brute force measures every term of every segment; the grid's queries measure each vertex's once.
  const bool at_u = opt_.brute_force || first_visit(s.from), at_v = opt_.brute_force || first_visit(s.to);
  limit_exact(f, s.u, s.v, r, limits, at_u, at_v);
  limits.settle(f.h);
}

// The limits on both sides, from the segments near the split: those within r of where the new segments
// could be for moves up to t, with t growing until both sides stop within it.
Reach Curves::reach(const SplitFrame& f, double r, std::uint32_t v) {
  const std::uint32_t self = out_[v];
  Reach limits;
  if (opt_.brute_force) {
    for (std::uint32_t id = 0; id < segments_.size(); ++id) limit(f, id, self, r, limits);
    return limits;
  }
  // The segments next along the curve first: they stop the point most often, and once both sides are
  // stuck the rest is skipped.
  std::uint32_t chain[4] = {none, none, none, none};
  const std::uint32_t before = prev_[v], after = next_[v];
  if (before != none) chain[0] = out_[before], chain[1] = prev_[before] != none ? out_[prev_[before]] : none;
  if (out_[after] != none) chain[2] = out_[after], chain[3] = out_[next_[after]];
  // Segments measured in a smaller box keep their limits when the box grows; only those not measured yet
  // (the new ones, and those the diamond test set aside for the smaller box) are looked at again.
  ++query_;
  for (double t = std::max(f.h, r);; t *= 2) {
    auto visit = [&](std::uint32_t id) {
      if (limits.stuck(f.h)) return;
      Segment& s = segments_[id];
      if (s.seen == query_ || apart(f, s, std::min(limits.positive, t), std::min(limits.negative, t), r)) return;
      s.seen = query_;
      limit(f, id, self, r, limits);
    };
    for (std::uint32_t id : chain)
      if (id != none && id != self) visit(id);
    // Only where the new segments can still go: the limits found so far bound that too.
    BBox2 box;
    for (Vec2 q : {f.a, f.b, f.at(std::min(t, limits.positive)), f.at(-std::min(t, limits.negative))}) box.add(q);
    grid_.visit({box.min - Vec2::all(r), box.max + Vec2::all(r)}, visit);
    if ((limits.positive <= t && limits.negative <= t) || t > far_) return limits;
  }
}

std::uint32_t Curves::split(std::uint32_t v, double r, int level, LevelReport& report) {
  const std::uint32_t w = next_[v];
  const SplitFrame f(at_[v], at_[w]);
  const Reach limits = reach(f, r, v);
  double t = chosen_move(limits);
  ++report.splits;
  if (std::abs(t) < stuck_fraction * f.h) {
    t = 0;
    ++report.stuck;
  }
  const auto p = static_cast<std::uint32_t>(at_.size());
  at_.push_back(f.at(t));
  level_.push_back(level);
  next_.push_back(w);
  next_[v] = p;
  prev_.push_back(v);
  prev_[w] = p;
  segments_[out_[v]].alive = false;
  out_[v] = add(at_[v], at_[p], v, p);
  out_.push_back(add(at_[p], at_[w], p, w));
  vertex_seen_.push_back(0);
  return p;
}

std::vector<std::uint32_t> Curves::chain(std::size_t i) const { return chain_vertices(first_[i], next_, none); }

Polyline Curves::result() const {
  Polyline out;
  std::vector<std::int32_t> level, curve;
  for (std::size_t i = 0; i < curves(); ++i) {
    std::vector<std::uint32_t> c = chain(i);
    if (closed_[i]) c.push_back(c.front());
    for (std::uint32_t v : c) {
      out.points.push_back(at_[v]);
      level.push_back(level_[v]);
    }
    out.close_path();
    curve.push_back(static_cast<std::int32_t>(i + 1));
  }
  out.point_fields.set(int_field("level", std::move(level)));
  out.cell_fields.set(int_field("curve", std::move(curve)));
  return out;
}

}  // namespace selfsim::exclusion
