#include "kernels/exclusion/start_check.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "kernels/base/check.h"
#include "kernels/base/error.h"
#include "kernels/geom/segment2.h"
#include "kernels/geom/segment_grid.h"

namespace selfsim::exclusion {

namespace {

std::string point_text(Vec2 p) { return "(" + number_text(p.x) + ", " + number_text(p.y) + ")"; }

struct StartSegment {
  Vec2 from, to;
  std::size_t curve, index;  // from 0
};

// Whether two start segments are allowed to meet: consecutive along one curve (also around a closed one).
bool consecutive(const Polyline& start, const StartSegment& s, const StartSegment& t) {
  if (s.curve != t.curve) return false;
  const std::size_t n = start.path(s.curve).size() - 1;
  const std::size_t lo = std::min(s.index, t.index), hi = std::max(s.index, t.index);
  return hi == lo + 1 || (exact_loop(start.path(s.curve)) && lo == 0 && hi == n - 1);
}

std::string segment_name(const StartSegment& s) {
  return "start curve " + std::to_string(s.curve + 1) + "'s segment " + std::to_string(s.index + 1);
}

}  // namespace

bool exact_loop(std::span<const Vec2> p) { return p.size() >= 4 && p.front() == p.back(); }

// Whether segment a-b meets the boundary anywhere but at an end that may touch it (a_may, b_may), exactly:
// the quick test by distance is too coarse for a short segment or one at a shallow angle to an edge.
bool meets_boundary(const Region& region, Vec2 a, Vec2 b, bool a_may, bool b_may, double tiny) {
  for (std::size_t e = 0; e < region.edges(); ++e) {
    const Vec2 p = region.edge_start(e), q = region.edge_end(e);
    if (!segments_meet(a, b, p, q) && segment_distance(a, b, p, q) > tiny) continue;
    const bool at_a = a_may && point_segment_distance(a, p, q) <= tiny;
    const bool at_b = b_may && point_segment_distance(b, p, q) <= tiny;
    if (!at_a && !at_b) return true;
    // Touching at an allowed end is fine unless the segment runs along the edge from there.
    const Vec2 other = at_a ? b : a;
    if (point_segment_distance(other, p, q) <= tiny) return true;
    const double along = std::abs(cross(q - p, other - (at_a ? a : b))) / norm(q - p);
    if (along <= tiny) return true;
  }
  return false;
}

void check_start(const Region& region, const Polyline& start, const Polyline& shown) {
  if (start.paths() == 0) throw Error("the start has no curve");
  const double tiny = 1e-12 * norm(region.bbox().size());
  std::vector<StartSegment> segments;
  for (std::size_t i = 0; i < start.paths(); ++i) {
    const auto p = start.path(i), q = shown.path(i);
    const std::string name = "start curve " + std::to_string(i + 1);
    if (p.size() < 2) throw Error(name + " needs at least one segment (two points)");
    const bool loop = exact_loop(p);
    for (std::size_t k = 0; k < p.size(); ++k) {
      if (!is_finite(p[k])) throw Error(name + "'s point " + std::to_string(k + 1) + " is not finite");
      if (!region.contains(p[k]))
        throw Error(name + "'s point " + std::to_string(k + 1) + " " + point_text(q[k]) + " lies outside the region");
      // Only an open curve's two ends may lie on the boundary.
      const bool end = !loop && (k == 0 || k + 1 == p.size());
      if (!end && region.distance(p[k]) <= tiny)
        throw Error(name + "'s point " + std::to_string(k + 1) + " " + point_text(q[k]) +
                    " lies on the region's boundary (a curve may touch it only at its own two ends)");
      if (k + 1 == p.size()) break;
      if (p[k] == p[k + 1])
        throw Error(name + "'s segment " + std::to_string(k + 1) + " has zero length (its points " +
                    std::to_string(k + 1) + " and " + std::to_string(k + 2) + " are both " + point_text(q[k]) + ")");
      // The segment without its ends must stay off the boundary.
      const Vec2 d = p[k + 1] - p[k];
      if (region.distance(p[k] + 1e-9 * d, p[k + 1] - 1e-9 * d) <= tiny &&
          meets_boundary(region, p[k], p[k + 1], !loop && k == 0, !loop && k + 2 == p.size(), tiny))
        throw Error(name + "'s segment " + std::to_string(k + 1) +
                    " crosses or touches the region's boundary (a curve may touch it only at its own two ends)");
      segments.push_back({p[k], p[k + 1], i, k});
    }
  }
  double length = 0;
  for (const StartSegment& s : segments) length += norm(s.to - s.from);
  SegmentGrid grid(region.bbox(),
                   std::max(length / static_cast<double>(segments.size()), norm(region.bbox().size()) * 1e-6));
  for (std::size_t s = 0; s < segments.size(); ++s)
    grid.insert(static_cast<std::uint32_t>(s), segments[s].from, segments[s].to);
  std::vector<std::uint32_t> near;
  for (std::size_t s = 0; s < segments.size(); ++s) {
    BBox2 box;
    box.add(segments[s].from);
    box.add(segments[s].to);
    grid.near(box, near);
    for (std::uint32_t t : near) {
      if (t <= s) continue;
      const StartSegment &x = segments[s], &y = segments[t];
      if (consecutive(start, x, y)) {  // they share one end; neither may fold back over the other
        const Vec2 far_x = x.from == y.from || x.from == y.to ? x.to : x.from;
        const Vec2 far_y = y.from == x.from || y.from == x.to ? y.to : y.from;
        if (point_segment_distance(far_x, y.from, y.to) > 0 && point_segment_distance(far_y, x.from, x.to) > 0)
          continue;
        throw Error(segment_name(x) + " folds back over " + segment_name(y) + ": the start curves must not overlap");
      }
      if (segments_meet(segments[s].from, segments[s].to, segments[t].from, segments[t].to))
        throw Error(segment_name(segments[s]) + " meets " + segment_name(segments[t]) +
                    ": the start curves must not cross or touch themselves or each other");
    }
  }
}

}  // namespace selfsim::exclusion
