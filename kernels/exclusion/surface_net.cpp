#include "kernels/exclusion/surface_net.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "kernels/base/error.h"
#include "kernels/exclusion/wall_reach.h"
#include "kernels/geom/field.h"

namespace selfsim::exclusion {
namespace {

constexpr std::uint32_t boundary_bit = 0x80000000u;  // grid ids of the region's boundary triangles

// A triangle's edge from corner k to corner k + 1, keyed by its ends' numbers.
struct HalfEdge {
  std::uint32_t lo, hi, triangle;
  int k;
};

bool overlapping(const BBox3& a, const BBox3& b) {
  return a.min.x <= b.max.x && a.max.x >= b.min.x && a.min.y <= b.max.y && a.max.y >= b.min.y && a.min.z <= b.max.z &&
         a.max.z >= b.min.z;
}

// The distance between two boxes: no point of one is nearer than this to a point of the other.
double box_distance(const BBox3& a, const BBox3& b) {
  const Vec3 gap = max_each(max_each(a.min - b.max, b.min - a.max), Vec3{});
  return norm(gap);
}

// The unit vector from edge a-b's line towards c, square to the edge.
Vec3 towards(Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 e = b - a, w = c - a;
  return normalized(w - (dot(w, e) / dot(e, e)) * e);
}

}  // namespace

Surfaces::Surfaces(const Mesh& boundary, const Mesh& start, double points, double triangles)
    : boundary_(boundary), far_(2 * norm(boundary.bbox().size())) {
  points_.reserve(static_cast<std::size_t>(points));
  level_.reserve(points_.capacity());
  triangles_.reserve(static_cast<std::size_t>(triangles));
  surface_.reserve(triangles_.capacity());
  points_ = start.points;
  level_.assign(points_.size(), 0);
  triangles_ = start.triangles;
  // Each face-connected piece of the start is one surface, numbered in the order of its first triangle.
  std::vector<std::uint32_t> root(points_.size());
  for (std::uint32_t i = 0; i < root.size(); ++i) root[i] = i;
  auto find = [&](std::uint32_t i) {
    while (root[i] != i) i = root[i] = root[root[i]];
    return i;
  };
  for (const Triangle& t : triangles_) root[find(t[0])] = find(t[1]), root[find(t[1])] = find(t[2]);
  std::vector<std::int32_t> number(points_.size(), 0);
  std::int32_t count = 0;
  for (const Triangle& t : triangles_) {
    std::int32_t& n = number[find(t[0])];
    if (n == 0) n = ++count;
    surface_.push_back(n);
  }
}

void Surfaces::subdivide(int level, double r) {
  // The edges, each once, in the order of their first appearance.
  std::vector<HalfEdge> half;
  half.reserve(3 * triangles_.size());
  for (std::uint32_t t = 0; t < triangles_.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = triangles_[t][k], b = triangles_[t][(k + 1) % 3];
      half.push_back({std::min(a, b), std::max(a, b), t, k});
    }
  std::sort(half.begin(), half.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return std::tie(x.lo, x.hi, x.triangle, x.k) < std::tie(y.lo, y.hi, y.triangle, y.k);
  });
  struct Edge {
    std::size_t first, count;  // its half edges in `half`
  };
  std::vector<Edge> edges;
  for (std::size_t i = 0; i < half.size();) {
    std::size_t j = i;
    while (j < half.size() && half[j].lo == half[i].lo && half[j].hi == half[i].hi) ++j;
    if (j - i > 2) throw Error("the surface has an edge shared by more than two triangles");
    edges.push_back({i, j - i});
    i = j;
  }
  std::sort(edges.begin(), edges.end(), [&](const Edge& x, const Edge& y) {
    return 3 * half[x.first].triangle + half[x.first].k < 3 * half[y.first].triangle + half[y.first].k;
  });
  // A midpoint for each edge, on the edge.
  const auto old_points = static_cast<std::uint32_t>(points_.size());
  std::vector<std::uint32_t> mid_of(3 * triangles_.size());  // triangle t's edge k -> its midpoint
  for (std::uint32_t e = 0; e < edges.size(); ++e)
    for (std::size_t i = edges[e].first; i < edges[e].first + edges[e].count; ++i)
      mid_of[3 * half[i].triangle + half[i].k] = old_points + e;
  for (const Edge& e : edges) {
    points_.push_back(0.5 * (points_[half[e.first].lo] + points_[half[e.first].hi]));
    level_.push_back(level);
  }
  // Each triangle c0 c1 c2 becomes its three corners' triangles (corner k's is 4t + k) and the middle one.
  // Copied, not moved: the vectors keep the capacity reserved for the whole run.
  const std::vector<Triangle> old = triangles_;
  const std::vector<std::int32_t> old_surface = surface_;
  triangles_.clear();
  surface_.clear();
  for (std::uint32_t t = 0; t < old.size(); ++t) {
    const Triangle& c = old[t];
    const std::uint32_t m0 = mid_of[3 * t], m1 = mid_of[3 * t + 1], m2 = mid_of[3 * t + 2];
    for (const Triangle& n :
         {Triangle{c[0], m0, m2}, Triangle{m0, c[1], m1}, Triangle{m2, m1, c[2]}, Triangle{m0, m1, m2}}) {
      triangles_.push_back(n);
      surface_.push_back(old_surface[t]);
    }
  }
  // Each midpoint's fan and line.
  mids_.assign(edges.size(), Midpoint{});
  for (std::uint32_t e = 0; e < edges.size(); ++e) {
    Midpoint& mid = mids_[e];
    mid.vertex = old_points + e;
    // Within triangle t, the ring from the edge's start c_k to its end c_k+1 passes the other two midpoints.
    auto part = [&](const HalfEdge& he, bool reversed) {
      const Triangle& c = old[he.triangle];
      const int k = he.k, k1 = (k + 1) % 3, k2 = (k + 2) % 3;
      std::array<std::uint32_t, 4> ring{c[k], mid_of[3 * he.triangle + k2], mid_of[3 * he.triangle + k1], c[k1]};
      std::array<std::uint32_t, 3> fan{4 * he.triangle + k, 4 * he.triangle + 3, 4 * he.triangle + k1};
      if (reversed) std::reverse(ring.begin(), ring.end());
      return std::pair{ring, fan};
    };
    const HalfEdge& first = half[edges[e].first];
    const Triangle& c = old[first.triangle];
    const Vec3 a = points_[c[first.k]], b = points_[c[(first.k + 1) % 3]], third = points_[c[(first.k + 2) % 3]];
    const auto [ring, fan] = part(first, false);
    for (int i = 0; i < 4; ++i) mid.ring[mid.ring_size++] = ring[i];
    for (int i = 0; i < 3; ++i) mid.fan[mid.fan_size++] = fan[i];
    mid.h = 0.5 * norm(b - a);
    const Vec3 u1 = towards(a, b, third);
    if (edges[e].count == 1) {
      mid.d = -u1;  // in the triangle's plane, away from it
      continue;
    }
    // The other triangle goes b -> a when the surface is consistently oriented; its ring part b ... a then
    // closes the ring (its ends are a and b already there).
    const HalfEdge& second = half[edges[e].first + 1];
    const Triangle& c2 = old[second.triangle];
    const auto [ring2, fan2] = part(second, c2[second.k] == c[first.k]);
    mid.ring[mid.ring_size++] = ring2[1];
    mid.ring[mid.ring_size++] = ring2[2];
    for (int i = 0; i < 3; ++i) mid.fan[mid.fan_size++] = fan2[i];
    mid.closed = true;
    // The dihedral angle's bisector: square to the edge and to u1 - u2, on the side of the first
    // triangle's normal.
    const Vec3 u2 = towards(a, b, points_[c2[(second.k + 2) % 3]]);
    Vec3 d = normalized(cross(b - a, u1 - u2));
    const Vec3 normal = cross(b - a, third - a);
    if (dot(d, normal) < 0) d = -d;
    mid.d = norm(d) > 0.5 ? d : normalized(normal);
  }
  // The neighbour grid: cells of 1.5 times the radius or the mean edge, whichever is larger.
  double length = 0;
  for (const Midpoint& m : mids_) length += 2 * m.h;
  const double mean = mids_.empty() ? 0 : 0.5 * length / static_cast<double>(mids_.size());
  BBox3 bounds = boundary_.bbox();
  grid_ = BoxGrid3(bounds, 1.5 * std::max({r, mean, 1e-9 * norm(bounds.size())}));
  order_rounds(std::max(r, 2 * mean));
  for (std::uint32_t t = 0; !walls_ && t < boundary_.triangles.size(); ++t) {
    BBox3 box;
    for (std::uint32_t v : boundary_.triangles[t]) box.add(boundary_.points[v]);
    grid_.insert(boundary_bit | t, box);
  }
  for (std::uint32_t t = 0; t < triangles_.size(); ++t) grid_.insert(t, triangle_box(t));
  if (along_ > 0 && !std::isinf(along_)) link_edges(r);
}

BBox3 Surfaces::triangle_box(std::uint32_t t) const {
  BBox3 box;
  for (std::uint32_t v : triangles_[t]) box.add(points_[v]);
  return box;
}

Reach Surfaces::reach(const Midpoint& mid, double r, Query& q, BBox3& looked) const {
  q.fit(triangles_.size(), boundary_.triangles.size(), points_.size());
  std::array<Vec3, 6> ring_at;
  for (int i = 0; i < mid.ring_size; ++i) ring_at[i] = points_[mid.ring[i]];
  const FanMove f{points_[mid.vertex],
                  mid.d,
                  {ring_at.data(), static_cast<std::size_t>(mid.ring_size)},
                  {mid.ring.data(), static_cast<std::size_t>(mid.ring_size)},
                  mid.closed};
  const FanView view(f);
  Reach limits;
  q.next();
  for (int i = 0; i < mid.fan_size; ++i) q.seen[mid.fan[i]] = q.stamp;  // the fan moves with the point
  // The fan's own static edges first: they keep it from folding onto itself.
  const int ring_edges = mid.closed ? mid.ring_size : mid.ring_size - 1;
  for (int i = 0; i < ring_edges; ++i) {
    const int j = (i + 1) % mid.ring_size;
    Obstacle own{{ring_at[i], ring_at[j], Vec3{}}, {mid.ring[i], mid.ring[j], no_vertex}, 2};
    if (along_ > 0) own.near = {true, true, false}, own.close = close_ * r;
    TermsWanted wanted;
    wanted.corner = {q.first_visit(mid.ring[i]), q.first_visit(mid.ring[j]), false};
    limit_fan(view, own, r, limits, wanted);
    limits.settle(mid.h);
  }
  // The fan where it starts: every term's distance is at least its box's distance from this box.
  BBox3 fan_box;
  for (int i = 0; i < mid.ring_size; ++i) fan_box.add(ring_at[i]);
  fan_box.add(f.m);
  looked.add(fan_box);
  if (limits.stuck(mid.h)) return limits;  // most moves of a deep level: nothing else can free them
  // The neighbourhood: searched along the mesh, or, infinite, every piece of the point's own surface.
  const auto own = static_cast<std::size_t>(surface_[mid.fan[0]]);
  const bool everywhere = std::isinf(along_) || (own < whole_.size() && whole_[own]);
  if (along_ > 0 && !everywhere) mark_neighbourhood(mid, along_ * r, q);
  // The neighbours within a few edges first: most moves a large radius stops are stuck by them, and
  // collecting the whole radius at once would take in all of a small surface for every move.
  double margin = std::min(r, 4 * mid.h);
  for (double t = mid.h;;) {
    BBox3 swept = fan_box;
    swept.add(f.m + std::min(t, limits.positive) * f.d);
    swept.add(f.m - std::min(t, limits.negative) * f.d);
    const BBox3 near{swept.min - Vec3::all(margin), swept.max + Vec3::all(margin)};
    looked.add(near);
    // The obstacles near, nearest first by their boxes' distance from the fan's.
    q.near.clear();
    grid_.visit(near, [&](std::uint32_t id) {
      std::uint32_t& seen = id & boundary_bit ? q.boundary_seen[id & ~boundary_bit] : q.seen[id];
      if (seen == q.stamp) return;
      const BBox3 box = obstacle(id).box();
      if (!overlapping(box, near)) return;  // looked at again if the box grows
      seen = q.stamp;
      q.near.push_back({box_distance(box, fan_box), id});
    });
    std::sort(q.near.begin(), q.near.end());
    for (const auto& [gap, id] : q.near) {
      // A term changes by at most |t| and may not come within its radius (r or less): none of this
      // obstacle's terms can act before |t| = gap - r, nor any later one's.
      if (limits.stuck(mid.h) || gap - r >= std::max(limits.positive, limits.negative)) break;
      Obstacle o = obstacle(id);
      TermsWanted wanted;
      if (!(id & boundary_bit))
        for (int k = 0; k < 3; ++k) {
          o.near[k] = everywhere ? surface_[id] == surface_[mid.fan[0]] : along_ > 0 && q.within(o.id[k], along_ * r);
          wanted.corner[k] = q.first_visit(o.id[k]);
          wanted.edge[k] = q.edges.first_visit(o.id[k], o.id[(k + 1) % 3]);  // a neighbour shares it
        }
      o.close = close_ * r;
      limit_fan(view, o, r, limits, wanted, id & boundary_bit ? std::array<VertexPieces*, 3>{} : q.pieces_of(o.id));
      limits.settle(mid.h);
    }
    if (limits.stuck(mid.h)) return limits;
    if (margin < r) {
      margin = r;  // the rest of the radius, before the move may go farther
      continue;
    }
    if ((limits.positive <= t && limits.negative <= t) || t > far_) break;
    t *= 2;
  }
  // The walls last, when the neighbours have narrowed the move: a move traced towards walls it will never
  // reach costs a few grid reads per step.
  if (walls_) limit_by_walls(f, *walls_, r, mid.h, far_, limits);
  return limits;
}

Obstacle Surfaces::obstacle(std::uint32_t id) const {
  if (id & boundary_bit) {
    const Triangle& c = boundary_.triangles[id & ~boundary_bit];
    return {{boundary_.points[c[0]], boundary_.points[c[1]], boundary_.points[c[2]]}};
  }
  const Triangle& c = triangles_[id];
  return {{points_[c[0]], points_[c[1]], points_[c[2]]}, {c[0], c[1], c[2]}};
}

void Surfaces::order_rounds(double reach) {
  // Cells of twice the reach a move usually has, in 8 colours by the parities of their coordinates: two
  // cells of one colour are a cell apart, so the moves of one round rarely see each other. (Larger cells
  // see each other less but leave dense places to long runs of small rounds: at 9 levels, 4 times took
  // 7,806 rounds and twice 2,233, with 1.7% of moves measured again.)
  const double cell = round_cells_ * reach;
  const BBox3 bounds = boundary_.bbox();
  struct Key {
    std::uint32_t colour, rank;
    std::uint64_t cell;
    std::uint32_t mid;
    bool operator<(const Key& o) const {
      return std::tie(colour, rank, cell, mid) < std::tie(o.colour, o.rank, o.cell, o.mid);
    }
  };
  std::vector<Key> keys(mids_.size());
  for (std::uint32_t e = 0; e < mids_.size(); ++e) {
    const Vec3 q = (1 / cell) * (points_[mids_[e].vertex] - bounds.min);
    const auto i = static_cast<std::uint64_t>(std::clamp(q.x, 0.0, 1e6)),
               j = static_cast<std::uint64_t>(std::clamp(q.y, 0.0, 1e6)),
               k = static_cast<std::uint64_t>(std::clamp(q.z, 0.0, 1e6));
    keys[e] = {static_cast<std::uint32_t>((i & 1) | (j & 1) << 1 | (k & 1) << 2), 0, (k << 40) | (j << 20) | i, e};
  }
  // Each cell's midpoints ranked in edge order.
  std::vector<Key> by_cell = keys;
  std::sort(by_cell.begin(), by_cell.end(),
            [](const Key& a, const Key& b) { return std::tie(a.cell, a.mid) < std::tie(b.cell, b.mid); });
  for (std::size_t n = 0; n < by_cell.size(); ++n)
    keys[by_cell[n].mid].rank = n > 0 && by_cell[n - 1].cell == by_cell[n].cell ? keys[by_cell[n - 1].mid].rank + 1 : 0;
  std::sort(keys.begin(), keys.end());
  order_.clear();
  rounds_.clear();
  for (std::size_t n = 0; n < keys.size(); ++n) {
    if (n == 0 || keys[n].colour != keys[n - 1].colour || keys[n].rank != keys[n - 1].rank) rounds_.push_back(n);
    order_.push_back(keys[n].mid);
  }
  rounds_.push_back(keys.size());
}

void Surfaces::grow(double r, LevelReport& report, Progress& progress, bool speculate) {
  struct Outcome {
    double t;
    BBox3 looked;  // what the move measured: no change elsewhere alters it
  };
  std::vector<Outcome> outcomes;

  std::vector<BBox3> changed;  // the fans the round has moved so far, where they were and where they went
  std::size_t done = 0;
  for (std::size_t round = 0; round + 1 < rounds_.size(); ++round) {
    const std::size_t begin = rounds_[round], end = rounds_[round + 1];
    if (done >> 8 != (done + end - begin) >> 8)
      progress.step(static_cast<double>(done) / static_cast<double>(mids_.size()));
    done += end - begin;
    // Every move of the round against the state before it, in parallel: nothing is written.
    outcomes.assign(end - begin, Outcome{});
    if (speculate)
      tbb::parallel_for(tbb::blocked_range<std::size_t>(begin, end, 4),
                        [&](const tbb::blocked_range<std::size_t>& range) {
                          Query& q = queries_.local();
                          for (std::size_t n = range.begin(); n < range.end(); ++n) {
                            if (progress.cancelled()) throw Cancelled();
                            Outcome& o = outcomes[n - begin];
                            o.t = chosen_move(reach(mids_[order_[n]], r, q, o.looked));
                          }
                        });
    // Then in order, each as if alone: a move whose measured box meets a fan an earlier move of the round
    // changed is measured again, so the result is the sequential one whatever the threads.
    changed.clear();
    for (std::size_t n = begin; n < end; ++n) {
      const Midpoint& mid = mids_[order_[n]];
      Outcome& o = outcomes[n - begin];
      if (std::any_of(changed.begin(), changed.end(), [&](const BBox3& b) { return overlapping(b, o.looked); })) {
        o.looked = {};
        o.t = chosen_move(reach(mid, r, queries_.local(), o.looked));
      }
      if (!speculate) o.t = chosen_move(reach(mid, r, queries_.local(), o.looked));
      ++report.splits;
      if (std::abs(o.t) < stuck_fraction * mid.h) {
        ++report.stuck;
        continue;
      }
      BBox3 fan;
      for (int i = 0; i < mid.fan_size; ++i) fan.add(triangle_box(mid.fan[i]));
      points_[mid.vertex] = points_[mid.vertex] + o.t * mid.d;
      for (int i = 0; i < mid.fan_size; ++i) {
        const BBox3 box = triangle_box(mid.fan[i]);
        grid_.insert(mid.fan[i], box);
        fan.add(box);
      }
      changed.push_back(fan);
    }
  }
}

double Surfaces::area() const {
  double a = 0;
  for (const Triangle& c : triangles_)
    a += 0.5 * norm(cross(points_[c[1]] - points_[c[0]], points_[c[2]] - points_[c[0]]));
  return a;
}

Mesh Surfaces::result() const {
  Mesh m;
  m.points = points_;
  m.triangles = triangles_;
  std::vector<std::int32_t> face_level(triangles_.size());
  for (std::size_t t = 0; t < triangles_.size(); ++t)
    face_level[t] = std::min({level_[triangles_[t][0]], level_[triangles_[t][1]], level_[triangles_[t][2]]});
  m.point_fields.set(int_field("level", level_));
  m.face_fields.set(int_field("level", std::move(face_level)));
  m.face_fields.set(int_field("surface", surface_));
  return m;
}

}  // namespace selfsim::exclusion
