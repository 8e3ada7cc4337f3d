#include "kernels/exclusion/exclusion_curve.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "kernels/exclusion/split_reach.h"
#include "kernels/exclusion/start_check.h"
#include "kernels/geom/check.h"
#include "kernels/geom/segment_grid.h"

namespace selfsim::exclusion {

namespace {

constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();

// A point that can move less than this fraction of its half segment on both sides stays at the midpoint.
constexpr double stuck_fraction = 1e-6;

// Bytes of working memory per point of the result, measured (README): vertices and their links, about one
// and a half segments of 40 bytes, their grid cells. Counted against the budget in points of 16 bytes.
constexpr double working_points_per_point = 12;

struct Segment {
  Vec2 u, v;
  std::uint32_t from = none, to = none;  // the curve's vertices at u and v (none for the boundary's)
  bool alive = true;
  std::uint32_t seen = 0;  // the query that last visited it (a grid lists a segment in several cells)
};

// Every curve as a chain of vertices; the live segments of the curves and of the region's boundary listed in
// a grid (not with brute_force, which measures them all).
class Curves {
 public:
  Curves(const Region& region, const Polyline& start, const CurveOptions& opt, double points);

  // Lists this moment's segments afresh, in a grid of the given cell size (dead segments dropped).
  void index(double cell);
  // Splits the segment that starts at vertex v with radius r; returns the new vertex.
  std::uint32_t split(std::uint32_t v, double r, int level, LevelReport& report);
  // Curve i's vertices in order from its first (a closed curve's first not repeated) and whether it is closed.
  std::vector<std::uint32_t> chain(std::size_t i) const;
  bool closed(std::size_t i) const { return closed_[i]; }
  std::size_t curves() const { return first_.size(); }
  double mean_length() const;
  Polyline result() const;

 private:
  Reach reach(const SplitFrame& f, double r, std::uint32_t v);
  void limit(const SplitFrame& f, std::uint32_t id, std::uint32_t self, double r, Reach& limits);
  std::uint32_t add(Vec2 u, Vec2 v, std::uint32_t from = none, std::uint32_t to = none);
  // Whether vertex x's own terms are still to be measured in this query (a vertex ends two segments).
  bool first_visit(std::uint32_t x);

  const Region& region_;
  const CurveOptions& opt_;
  std::vector<Vec2> at_;
  std::vector<std::uint32_t> next_, prev_, out_;  // next and previous vertex along the curve, segment
                                                  // starting here (or none)
  std::vector<std::int32_t> level_;               // the level each vertex was made at
  std::vector<std::uint32_t> first_;              // each curve's first vertex
  std::vector<bool> closed_;
  std::vector<Segment> segments_;
  SegmentGrid grid_;
  std::uint32_t query_ = 0;
  std::vector<std::uint32_t> vertex_seen_;  // the query that last measured each vertex's terms
  double far_;                              // no point moves farther than this: the region's size
};

Curves::Curves(const Region& region, const Polyline& start, const CurveOptions& opt, double points)
    : region_(region), opt_(opt), far_(2 * norm(region.bbox().size())) {
  at_.reserve(static_cast<std::size_t>(points));
  next_.reserve(at_.capacity());
  prev_.reserve(at_.capacity());
  out_.reserve(at_.capacity());
  level_.reserve(at_.capacity());
  for (std::size_t i = 0; i < start.paths(); ++i) {
    const auto p = start.path(i);
    const bool loop = closed_path(p);
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

void Curves::index(double cell) {
  segments_.clear();
  // This level's segments, then two for each split: no reallocation while the level runs.
  segments_.reserve(region_.edges() + 3 * at_.size());
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
}

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
    BBox2 box;
    for (Vec2 q : {f.a, f.b, f.at(t), f.at(-t)}) box.add(q);
    auto visit = [&](std::uint32_t id) {
      // Once both sides are below the stuck threshold the point stays at the midpoint, whatever else is near.
      if (limits.positive < stuck_fraction * f.h && limits.negative < stuck_fraction * f.h) return;
      Segment& s = segments_[id];
      if (s.seen == query_ || apart(f, s, std::min(limits.positive, t), std::min(limits.negative, t), r)) return;
      s.seen = query_;
      limit(f, id, self, r, limits);
    };
    for (std::uint32_t id : chain)
      if (id != none && id != self) visit(id);
    grid_.visit({box.min - Vec2::all(r), box.max + Vec2::all(r)}, visit);
    if ((limits.positive <= t && limits.negative <= t) || t > far_) return limits;
  }
}

std::uint32_t Curves::split(std::uint32_t v, double r, int level, LevelReport& report) {
  const std::uint32_t w = next_[v];
  const SplitFrame f(at_[v], at_[w]);
  const Reach limits = reach(f, r, v);
  double t = limits.negative > limits.positive * (1 + 1e-9) ? -limits.negative : limits.positive;
  if (!std::isfinite(t))
    throw Error("a split found nothing to stop its point (a fault in selfsim: please report the recipe)");
  t *= 1 - 1e-9;  // a rounding short of the limit, so that the radius still holds once the point is stored
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

std::vector<std::uint32_t> Curves::chain(std::size_t i) const {
  std::vector<std::uint32_t> c;
  std::uint32_t v = first_[i];
  do {
    c.push_back(v);
    v = next_[v];
  } while (v != none && v != first_[i]);
  return c;
}

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

// Seconds since `from`.
double since(std::chrono::steady_clock::time_point from) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - from).count();
}

void grow_breadth(Curves& c, const CurveOptions& opt, double total_splits, Progress& progress,
                  std::vector<LevelReport>& reports) {
  double r = opt.radius, done = 0;
  for (int level = 1; level <= opt.levels; ++level, r *= opt.factor) {
    const auto begun = std::chrono::steady_clock::now();
    LevelReport report;
    // Cells of 1.5 times the radius or the segments' mean length, whichever is larger (measured fastest
    // among 0.5 to 2 times), and not so small that a segment crossing the region fills millions of them.
    c.index(1.5 * std::max({r, c.mean_length(), 1e-6 * opt.radius}));
    const bool backwards = opt.scan == Scan::alternate && level % 2 == 0;
    for (std::size_t q = 0; q < c.curves(); ++q) {
      const std::size_t i = backwards ? c.curves() - 1 - q : q;
      const std::vector<std::uint32_t> chain = c.chain(i);
      const std::size_t n = c.closed(i) ? chain.size() : chain.size() - 1;
      for (std::size_t step = 0; step < n; ++step) {
        if ((report.splits & 1023) == 0) progress.step(done / total_splits);
        c.split(chain[backwards ? n - 1 - step : step], r, level, report);
        ++done;
      }
    }
    report.seconds = since(begun);
    reports.push_back(report);
  }
}

struct DepthRun {
  Curves& c;
  const CurveOptions& opt;
  double total_splits, done = 0;
  Progress& progress;
  std::vector<LevelReport>& reports;

  void split(std::uint32_t v, int depth, double r) {
    if (depth > opt.levels) return;
    if ((static_cast<std::size_t>(done) & 1023) == 0) progress.step(done / total_splits);
    const std::uint32_t p = c.split(v, r, depth, reports[depth - 1]);
    ++done;
    split(v, depth + 1, r * opt.factor);
    split(p, depth + 1, r * opt.factor);
  }
};

void grow_depth(Curves& c, const CurveOptions& opt, double total_splits, Progress& progress,
                std::vector<LevelReport>& reports) {
  const auto begun = std::chrono::steady_clock::now();
  reports.assign(opt.levels, LevelReport{});
  // One grid for the whole run, with cells about the last level's radius or segment length.
  const double last_r = opt.radius * std::pow(opt.factor, opt.levels - 1);
  c.index(std::max({last_r, c.mean_length() * std::ldexp(1.0, -opt.levels), 1e-6 * opt.radius}));
  DepthRun run{c, opt, total_splits, 0, progress, reports};
  for (std::size_t i = 0; i < c.curves(); ++i) {
    const std::vector<std::uint32_t> chain = c.chain(i);
    const std::size_t n = c.closed(i) ? chain.size() : chain.size() - 1;
    for (std::size_t k = 0; k < n; ++k) run.split(chain[k], 1, opt.radius);
  }
  if (!reports.empty()) reports.back().seconds = since(begun);
}

}  // namespace

void CurveOptions::validate() const {
  check_between(radius, 1e-300, 1e300, "option 'radius'");
  if (!(factor > 0 && factor <= 1)) throw Error("option 'factor' must be in (0, 1], got " + number_text(factor));
  check_range(levels, 0, 40, "option 'levels'");
}

std::size_t CurveResult::stuck() const {
  std::size_t s = 0;
  for (const LevelReport& l : levels) s += l.stuck;
  return s;
}

double curve_size(const Polyline& start, int levels) {
  double points = 0;
  for (std::size_t i = 0; i < start.paths(); ++i)
    points += static_cast<double>(start.path(i).size() - 1) * std::ldexp(1.0, levels) + 1;
  return points;
}

double working_size(const Polyline& start, int levels) {
  return curve_size(start, levels) * (1 + working_points_per_point);
}

namespace {

// The region and starts moved to the origin and scaled by a power of two to a size about 1: the closed-form
// limits square coordinates up to four times over, which would overflow or underflow far from that size.
struct Normalised {
  Vec2 centre;
  double scale;
  Vec2 to(Vec2 p) const { return scale * (p - centre); }
  Vec2 from(Vec2 q) const { return (1 / scale) * q + centre; }
};

Normalised normalised(const Region& region) {
  const BBox2 box = region.bbox();
  const double side = std::max(box.size().x, box.size().y);
  return {0.5 * (box.min + box.max), std::ldexp(1.0, -std::ilogb(side))};
}

}  // namespace

CurveResult exclusion_curve(const Region& region, const Polyline& start, const CurveOptions& opt, Progress& progress) {
  opt.validate();
  const double points = curve_size(start, opt.levels);
  check_budget(working_size(start, opt.levels), opt.budget,
               "levels = " + std::to_string(opt.levels) + " (" + count_text(points) + " curve points, each " +
                   count_text(1 + working_points_per_point) + " budget points with its working memory)");
  const Normalised n = normalised(region);
  std::vector<std::vector<Vec2>> rings;
  for (const auto& ring : region.rings()) {
    rings.emplace_back();
    for (Vec2 p : ring) rings.back().push_back(n.to(p));
  }
  const Region local(std::move(rings));
  Polyline local_start = start;
  for (Vec2& p : local_start.points) p = n.to(p);
  check_start(local, local_start, start);
  // The last level's radius must stay well above rounding at the region's size.
  const double last = opt.radius * std::pow(opt.factor, std::max(opt.levels - 1, 0)) * n.scale;
  if (opt.levels > 0 && !(last >= 1e-12))
    throw Error("option 'radius' falls to " + number_text(last / n.scale) + " at level " + std::to_string(opt.levels) +
                " (factor " + number_text(opt.factor) + "), below 1e-12 of the region's size: raise 'radius' or " +
                "'factor', or lower 'levels'");
  CurveOptions local_opt = opt;
  local_opt.radius = opt.radius * n.scale;
  progress.start("exclusion curve");
  Curves c(local, local_start, local_opt, points);
  CurveResult result;
  const double splits = points - static_cast<double>(start.points.size());
  if (opt.order == Order::breadth)
    grow_breadth(c, local_opt, splits, progress, result.levels);
  else
    grow_depth(c, local_opt, splits, progress, result.levels);
  result.curve = c.result();
  // Back to the caller's coordinates, the start points exactly as given.
  const Field* made = result.curve.point_fields.find("level");
  for (std::size_t i = 0; i < result.curve.paths(); ++i) {
    const auto given = start.path(i);
    std::size_t k = 0;
    for (std::size_t j = result.curve.path_begin(i); j < result.curve.path_ends[i]; ++j)
      result.curve.points[j] = made->at(j) == 0 ? given[k++] : n.from(result.curve.points[j]);
  }
  if (!result.curve.finite()) throw Error("the exclusion curve has non-finite points");
  return result;
}

}  // namespace selfsim::exclusion
