#include "kernels/region/region.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "kernels/base/check.h"
#include "kernels/base/error.h"
#include "kernels/geom/segment2.h"

namespace selfsim {

namespace {

std::string ring_name(std::size_t r) { return r == 0 ? "the outer ring" : "hole " + std::to_string(r); }

// The grid's cell: twice the median edge, but no smaller than a 64th of the longest, so that no edge covers
// more than about 65 × 65 cells.
double cell_size(const std::vector<Vec2>& starts, const std::vector<Vec2>& ends) {
  std::vector<double> lengths;
  for (std::size_t e = 0; e < starts.size(); ++e) lengths.push_back(norm(ends[e] - starts[e]));
  const double longest = *std::max_element(lengths.begin(), lengths.end());
  std::nth_element(lengths.begin(), lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2), lengths.end());
  return std::max(2 * lengths[lengths.size() / 2], longest / 64);
}

// Whether p is inside ring (even-odd crossing count; points on it count as inside).
bool inside_ring(const std::vector<Vec2>& ring, Vec2 p) {
  bool in = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Vec2 a = ring[j], b = ring[i];
    if (point_segment_distance(p, a, b) == 0) return true;
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
  }
  return in;
}

}  // namespace

void Region::build(std::vector<std::vector<Vec2>> rings) {
  if (rings.empty()) throw Error("a region needs an outer ring of at least 3 points");
  for (std::size_t r = 0; r < rings.size(); ++r) {
    auto& ring = rings[r];
    if (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
    if (ring.size() < 3) throw Error(ring_name(r) + " needs at least 3 points, got " + std::to_string(ring.size()));
    for (std::size_t i = 0; i < ring.size(); ++i) {
      if (!is_finite(ring[i])) throw Error(ring_name(r) + " has a non-finite point " + std::to_string(i + 1));
      if (ring[i] == ring[(i + 1) % ring.size()])
        throw Error(ring_name(r) + " has a zero-length edge at its point " + std::to_string(i + 1));
      box_.add(ring[i]);
      starts_.push_back(ring[i]);
      ends_.push_back(ring[(i + 1) % ring.size()]);
    }
  }
  if (!(std::isfinite(box_.size().x) && std::isfinite(box_.size().y)))
    throw Error("the region's extent overflows (coordinates up to about 1e300 in size are supported)");
  rings_ = std::move(rings);
  grid_ = SegmentGrid(box_, cell_size(starts_, ends_));
  for (std::size_t e = 0; e < starts_.size(); ++e) grid_.insert(static_cast<std::uint32_t>(e), starts_[e], ends_[e]);
}

Region::Region(std::vector<std::vector<Vec2>> rings) {
  build(std::move(rings));
  check_rings();
}

Region Region::moved(Vec2 centre, double scale) const {
  std::vector<std::vector<Vec2>> rings = rings_;
  for (auto& ring : rings)
    for (Vec2& p : ring) p = scale * (p - centre);
  Region r;
  r.build(std::move(rings));
  return r;
}

void Region::check_rings() const {
  // Rings simple and apart: no two edges meet unless they follow each other around one ring.
  std::vector<std::size_t> ring_of, first_of;
  for (std::size_t r = 0, e = 0; r < rings_.size(); ++r) {
    first_of.push_back(e);
    for (std::size_t i = 0; i < rings_[r].size(); ++i, ++e) ring_of.push_back(r);
  }
  auto adjacent = [&](std::size_t e, std::size_t f) {
    if (ring_of[e] != ring_of[f]) return false;
    const std::size_t n = rings_[ring_of[e]].size(), i = e - first_of[ring_of[e]], j = f - first_of[ring_of[f]];
    return (i + 1) % n == j || (j + 1) % n == i;
  };
  for (std::size_t e = 0; e < starts_.size(); ++e) {
    BBox2 box;
    box.add(starts_[e]);
    box.add(ends_[e]);
    for (std::uint32_t f : grid_.near(box)) {
      if (f <= e || adjacent(e, f) || !segments_meet(starts_[e], ends_[e], starts_[f], ends_[f])) continue;
      const std::size_t re = ring_of[e], rf = ring_of[f];
      const std::string which = "edge " + std::to_string(e - first_of[re] + 1) + " of " + ring_name(re) + " and edge " +
                                std::to_string(f - first_of[rf] + 1) + " of " + ring_name(rf);
      throw Error(re == rf ? ring_name(re) + " crosses or touches itself: " + which
                           : "two rings cross or touch: " + which);
    }
  }
  for (std::size_t r = 1; r < rings_.size(); ++r) {
    if (!inside_ring(rings_[0], rings_[r][0])) throw Error(ring_name(r) + " lies outside the outer ring");
    for (std::size_t s = 1; s < r; ++s)
      if (inside_ring(rings_[s], rings_[r][0]) || inside_ring(rings_[r], rings_[s][0]))
        throw Error(ring_name(r) + " and " + ring_name(s) + " overlap: holes must lie apart");
  }
  // A ring enclosing no area (all its points on one line) is a slit, not a region (a simple ring
  // of three or more edges can enclose none only by lying on one line, which the crossing test lets through).
  for (std::size_t r = 0; r < rings_.size(); ++r) {
    double twice_area = 0;
    const Vec2 o = rings_[r][0];
    for (std::size_t i = 1; i + 1 < rings_[r].size(); ++i) twice_area += cross(rings_[r][i] - o, rings_[r][i + 1] - o);
    if (twice_area == 0) throw Error(ring_name(r) + " encloses no area (its points lie on one line)");
  }
}

bool Region::contains(Vec2 p) const {
  if (!inside_ring(rings_[0], p)) return false;
  for (std::size_t r = 1; r < rings_.size(); ++r)
    if (inside_ring(rings_[r], p) && distance(p) > 0) return false;
  return true;
}

double Region::distance_within(const BBox2& box, Vec2 a, Vec2 b) const {
  // Every edge lies in the region's box: the query never visits cells beyond it, however far the segment.
  BBox2 clipped;
  clipped.min = max_each(box.min, box_.min);
  clipped.max = min_each(box.max, box_.max);
  double best = std::numeric_limits<double>::infinity();
  if (clipped.min.x > clipped.max.x || clipped.min.y > clipped.max.y) return best;
  for (std::uint32_t e : grid_.near(clipped)) best = std::min(best, segment_distance(a, b, starts_[e], ends_[e]));
  return best;
}

double Region::distance(Vec2 p) const { return distance(p, p); }

double Region::distance(Vec2 a, Vec2 b) const {
  // Look in a box around the segment, growing it while the nearest edge found is beyond its reach (a nearer
  // edge would lie in the box); past 64 cells the grid costs more than measuring every edge.
  BBox2 seg;
  seg.add(a);
  seg.add(b);
  for (double reach = grid_.cell(); reach <= 64 * grid_.cell(); reach *= 4) {
    BBox2 box = seg;
    box.min = box.min - Vec2{reach, reach};
    box.max = box.max + Vec2{reach, reach};
    const double d = distance_within(box, a, b);
    if (d <= reach) return d;
  }
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t e = 0; e < starts_.size(); ++e) best = std::min(best, segment_distance(a, b, starts_[e], ends_[e]));
  return best;
}

}  // namespace selfsim
