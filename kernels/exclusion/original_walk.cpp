// The limits of one split through the grid: the two walks of original_grid.h, and what each side may skip
// (every skip is proved there, points 1 to 4, or below; the rest is measured exactly as his program does).
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "kernels/exclusion/original_chains.h"

namespace selfsim::exclusion::original {

// One side's walk: its obstacles, when it may stop, how far its vertices and crossings can matter.
struct Chains::Walker {
  const Chains& c;
  const Frame& f;
  Limits& l;
  std::uint32_t a, b, self;  // the split's ends and its segment record
  bool positive;
  double round;  // a bound far above the rounding of a point's signed distance from the bisector
  double noise;  // |computed crossing − true crossing|·|d·N1| is below this for every segment (point 1)
  double side;   // a vertex of this side lies no farther than this on the other (point 2)

  double limit() const { return positive ? l.positive : -l.negative; }
  bool finished() const { return positive ? l.positive <= 0 : -l.negative <= l.positive; }
  // Position along this side, from M.
  double along(Vec2 p) const { return positive ? dot2(f.n0, p - f.m) : -dot2(f.n0, p - f.m); }

  // Y(c) of point 2 with c, ε and r enlarged far beyond the rounding of a computed tangent and of its
  // crossing (kept until the limit changes).
  double reach() const {
    const double limit = this->limit();
    if (limit != reach_for_) {
      reach_for_ = limit;
      if (limit >= unbounded) {
        reach_ = std::numeric_limits<double>::infinity();
      } else {
        const double slack =
            1e-6 * (f.h + f.r + limit) + 1e-11 * (c.size_ + c.size_ * c.size_ + limit) * (1 + limit / f.h);
        const double lim = limit + slack, eps = f.eps + slack, r = f.r * (1 + 1e-6) + round;
        reach_ = lim + (eps * r + r * std::sqrt(std::max(lim, eps) * std::max(lim, eps) + f.h * f.h)) / f.h;
      }
    }
    return reach_;
  }
  mutable double reach_for_ = -1, reach_ = 0;

  // A vertex beyond the reach cannot lower this side's limit; one clearly on the other side gives this
  // side nothing (the other side's walk reaches it if that side still needs it).
  template <class List>
  void vertices(const List& list, double reach) const {
    list.each([&](const VertexEntry& e) {
      const double y = along(e.at);
      if (y > reach || y < -side || e.id == a || e.id == b) return;
      vertex_test(f, e.at, l);
    });
  }

  template <class List>
  void segments(const List& list) const {
    list.each([&](const SegmentEntry& e) {
      // Both ends clearly on one side of the bisector: its test computes s outside [0, 1] (`round` is far
      // above the rounding of both distances and of d·N1, so |s| > 1 + 1e-14 there).
      const double gp = f.c1 + dot2(f.n1, e.from), gq = f.c1 + dot2(f.n1, e.to);
      if ((gp > round && gq > round) || (gp < -round && gq < -round)) return;
      crossing(e);
    });
  }

  [[gnu::noinline]] void crossing(const SegmentEntry& e) const {
    if (e.id == self || !c.alive_[e.id] || c.seen_[e.id] == c.walks_) return;
    c.seen_[e.id] = c.walks_;
    if (!useless(e.from, e.to)) segment_test(f, e.from, e.to, l);
  }

  // Whether segment p-q, which meets the bisector between its ends' positions along this side, cannot
  // give this side a candidate below its limit. Only said of segments at more than 1e-4 radians from the
  // bisector ((d·N1)² ≥ 1e-8·|d|²), whose d·N1 is then good to 1e-11 of itself. Its computed crossing T
  // is within noise/|d·N1| of the true one, and 1/S, the computed 1/sqrt(1 − κ²), exceeds |d|/|d·N1| by
  // less than 1e-7 of itself. So (a) if even its farthest end plus noise/|d·N1| lies behind M, T < 0 and
  // its candidate is the other side's; (b) its candidate T − r/S is at least
  // nearest − (r·(1 + 1e-5)·|d| + noise)/|d·N1|.
  bool useless(Vec2 p, Vec2 q) const {
    const Vec2 d = q - p;
    const double den = std::abs(dot2(d, f.n1)), dd = d.x * d.x + d.y * d.y;
    if (!(den * den >= 1e-8 * dd)) return false;
    const double tp = along(p), tq = along(q);
    if ((std::max(tp, tq) + round) * den + 2 * noise < 0) return true;
    const double gap = std::min(tp, tq) - round - limit();
    return gap > 0 && gap * den >= (f.r * (1 + 1e-5) * std::sqrt(dd) + 2 * noise) * (1 + 1e-9);
  }

  // The direction bins (ObstacleGrid::direction_bins) of the segments that can still matter to this side
  // if they cross it in the part [nearest, farthest] of a strip; by `useless`, ahead of the limit only
  // sines below (r·(1 + 1e-5) + 2·noise/L)/(nearest − limit), and behind M only sines below
  // 2·noise/(L·|farthest|), L the level's shortest segment. At least 1e-4 (the sines `useless` leaves
  // alone), as angles: asin σ ≤ σ·π/2, widened by 1e-3 radians for the rounding of angles.
  ObstacleGrid::Bins directions(double nearest, double farthest, double angle) const {
    double sine = 1;
    if (farthest < -round) {
      sine = 2 * noise / (c.shortest_ * (-farthest - round));
    } else {
      const double gap = nearest - round - limit();
      if (gap > 0) sine = (f.r * (1 + 1e-5) + 2 * noise / c.shortest_) / gap;
    }
    sine = std::max(sine, 1e-4);
    if (!(sine < 1)) return ~ObstacleGrid::Bins{0};
    return ObstacleGrid::direction_bins(angle, sine * (std::numbers::pi / 2) + 1e-3);
  }
};

void Chains::limits_grid(const Frame& f, std::uint32_t a, std::uint32_t b, Limits& l) const {
  const std::uint32_t self = out_[a];
  for (std::uint32_t v : outside_vertices_)
    if (v != a && v != b) vertex_test(f, at_[v], l);
  for (std::uint32_t id : outside_segments_)
    if (id != self && alive_[id]) segment_test(f, from_[id], to_[id], l);
  // A point's computed signed distances are good to a few roundings of size²; a segment's crossing's
  // numerator too, over its sine; a vertex's side (N0·p + c0, c0 divided by |B − A| = 2h) likewise.
  const double round = 1e-12 * (size_ + size_ * size_) + grid_.pad();
  const double noise = 1e-14 * (size_ + size_ * size_);
  const double side = noise / f.h + round;
  const double behind = 2 * noise / f.eps + round;  // |d·N1| ≥ ε for every segment the test accepts
  const double width = (f.h + f.r) * (1 + 1e-9) + round;
  Walker up{*this, f, l, a, b, self, true, round, noise, side};
  ++walks_;
  grid_.walk(f.m, f.n0, behind, side, width, up);
  Walker down{*this, f, l, a, b, self, false, round, noise, side};
  ++walks_;
  grid_.walk(f.m, {-f.n0.x, -f.n0.y}, behind, side, width, down);
}

}  // namespace selfsim::exclusion::original
