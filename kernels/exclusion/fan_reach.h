// How far one obstacle lets a new point of an exclusion surface move (seed 004's closing section, in 3D:
// every triangle split 1 -> 4 at its edge midpoints, each midpoint moved along a line perpendicular to its
// edge). Pure geometry: the caller collects the obstacles near the move and keeps the smallest reach on
// each side.
//
// The point p(t) = m + t·d moves continuously away from the midpoint m. The triangles that have p as a
// corner (its fan) are p with each two consecutive points of its ring. They must keep the radius r from
// each obstacle: another triangle, or a segment or point (the fan's own static edges take part that way,
// so that the fan cannot fold onto itself). As in 2D (split_reach.h), the distance between a fan triangle
// and an obstacle is the least of distances between a point and a triangle or between two segments, and the
// ones that change with t are the terms:
//   - the point term: p to the obstacle;
//   - a corner term: an obstacle corner w to a fan triangle (p, x, y);
//   - an edge term: an obstacle edge u-v to a spoke p-z of the fan.
// Pairs that share a vertex (by number) are not measured: they meet there by construction. A term already
// below r where the move starts may not get any smaller (reach.h). Each term's set of t where it is too
// small is one interval: the fan triangle (or spoke) meets the convex set of points within the radius of the
// obstacle's piece exactly when p lies in that set's shadow from the triangle's static edge (or the spoke's
// static end), which is convex: its points are (1 + λ)·z - λ·s for z in the convex set, s in the static
// piece and λ >= 0, and the midpoint of two such points is another (λ the mean, z and s weighted means).
// The interval comes in closed form from the quadratics of its pieces.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>

#include "kernels/exclusion/reach.h"
#include "kernels/geom/bbox.h"
#include "kernels/geom/vec2.h"
#include "kernels/geom/vec3.h"

namespace selfsim::exclusion {

inline constexpr std::uint32_t no_vertex = 0xffffffffu;

inline constexpr std::size_t max_ring = 6;  // a midpoint's fan has 4 or 6 ring points

// The moving point and its fan.
struct FanMove {
  Vec3 m, d;                               // where the point starts, and its line's unit direction
  std::span<const Vec3> ring;              // the fan's other corners in order around p (2 to max_ring)
  std::span<const std::uint32_t> ring_id;  // their vertex numbers
  bool closed = false;                     // the last and first ring points make a triangle with p too
};

// An obstacle: a triangle (3 corners), a segment (2) or a point (1), with its corners' vertex numbers
// (no_vertex for corners no fan can share, such as the region's boundary).
struct Obstacle {
  std::array<Vec3, 3> at;
  std::array<std::uint32_t, 3> id{no_vertex, no_vertex, no_vertex};
  int corners = 3;
  // Corners in the moving point's neighbourhood: the terms of a near corner, of an edge between two near
  // corners and (all near) of the point with the whole obstacle keep `close` instead of r once closer than r
  // (reach.h, term_radius).
  std::array<bool, 3> near{false, false, false};
  double close = 0;

  BBox3 box() const {
    BBox3 b;
    for (int k = 0; k < corners; ++k) b.add(at[k]);
    return b;
  }
};

// Which of an obstacle's corner and edge terms to measure (its point term always is): a caller that has
// measured a corner or edge already (it belongs to a neighbouring obstacle too) saves the work. Edge k joins
// corners k and k + 1.
struct TermsWanted {
  std::array<bool, 3> corner{true, true, true}, edge{true, true, true};
};

// The sets of one obstacle corner w that the terms of one move share, solved once at the full radius: where
// the point comes within r of w, and where w comes within r of the spoke from each ring point. A vertex of
// the surface belongs to several obstacles, and each of its terms with a fan triangle or spoke needs them.
struct VertexPieces {
  static constexpr unsigned point_known = 1u << 7;
  Interval point;
  std::array<Interval, max_ring> shadow;  // by ring position
  unsigned known = 0;                     // bit j: shadow[j] solved; point_known: point solved
};

// A box in the coordinates of a frame square to a move's line: two across it (`flat`, the line seen end
// on), one along it. Such boxes follow the move, which only changes the coordinate along.
struct FrameBox {
  Vec2 lo = Vec2::all(unbounded), hi = Vec2::all(-unbounded);
  double along_lo = unbounded, along_hi = -unbounded;

  void add(Vec2 flat, double along) {
    lo = {std::min(lo.x, flat.x), std::min(lo.y, flat.y)}, hi = {std::max(hi.x, flat.x), std::max(hi.y, flat.y)};
    along_lo = std::min(along_lo, along), along_hi = std::max(along_hi, along);
  }
  // The squared gap to another box: no point of one is nearer the other.
  double gap2(const FrameBox& o) const {
    const double x = std::max({lo.x - o.hi.x, o.lo.x - hi.x, 0.0}), y = std::max({lo.y - o.hi.y, o.lo.y - hi.y, 0.0}),
                 z = std::max({along_lo - o.along_hi, o.along_lo - along_hi, 0.0});
    return x * x + y * y + z * z;
  }
};

// A move's fan prepared once for every obstacle it meets: its ring from m, and in the frame e1, e2, d.
struct FanView {
  explicit FanView(const FanMove& f);  // f must outlive the view
  Vec2 flat_of(Vec3 v) const { return {dot(v, e1), dot(v, e2)}; }
  double along_of(Vec3 v) const { return dot(v, move.d); }

  const FanMove& move;
  Vec3 e1, e2;
  std::array<Vec3, max_ring> ring;
  std::array<Vec2, max_ring> flat;
  std::array<double, max_ring> along;
  FrameBox box;  // the ring's
};

// Narrows `reach` by what obstacle `o` allows the fan with radius r, exactly. `pieces`: for each corner of
// the obstacle, its shared sets for this move, filled as they are solved (null: solved afresh).
void limit_fan(const FanView& fan, const Obstacle& o, double r, Reach& reach, const TermsWanted& wanted = {},
               const std::array<VertexPieces*, 3>& pieces = {});
inline void limit_fan(const FanMove& f, const Obstacle& o, double r, Reach& reach, const TermsWanted& wanted = {},
                      const std::array<VertexPieces*, 3>& pieces = {}) {
  limit_fan(FanView(f), o, r, reach, wanted, pieces);
}

}  // namespace selfsim::exclusion
