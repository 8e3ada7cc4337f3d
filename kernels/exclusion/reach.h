// How far a split point may move along its line, on each side, as the obstacles near it narrow the move:
// what the exclusion curve (split_reach.h, seed 004) and the exclusion surface (fan_reach.h, its 3D
// extension) share. A "term" is one distance the move changes (the point to an obstacle, an obstacle point
// to a new segment or triangle, ...); each has its own set of t where it is too small.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

#include "kernels/base/check.h"
#include "kernels/exclusion/line_intervals.h"

namespace selfsim::exclusion {

// A point that can move less than this fraction of its half segment (or half edge) on both sides stays at
// the midpoint, and is counted as stuck.
inline constexpr double stuck_fraction = 1e-6;

// How far the point may move: t in [0, positive] along the line's direction, in [0, negative] against it.
struct Reach {
  double positive = unbounded, negative = unbounded;

  // Both sides below the stuck threshold for half length h: the point stays at the midpoint, whatever else
  // is near.
  bool stuck(double h) const { return positive < stuck_fraction * h && negative < stuck_fraction * h; }
  // A side stopped below the threshold can only decide the split by leaving the point at the midpoint,
  // whatever its exact value: as 0 it lets the terms that only narrow it be skipped.
  void settle(double h) {
    if (positive < stuck_fraction * h) positive = 0;
    if (negative < stuck_fraction * h) negative = 0;
  }

  // Stops both sides at the first t of `violated` (a violation around t = 0 stops both at once).
  void block(Interval violated) {
    if (violated.empty()) return;
    if (violated.lo >= 0) {
      positive = std::min(positive, violated.lo);
    } else if (violated.hi <= 0) {
      negative = std::min(negative, -violated.hi);
    } else {
      positive = negative = 0;
    }
  }
};

// The radius a term must keep: r, or, when it starts below r at d0 (inherited from a coarser level, where
// the radius was larger but the split's neighbours were excepted), d0 itself less a hair, so that it may
// not get any smaller and t = 0 stays outside its set. Zero when the term starts touching. `close` > 0: the
// term is between neighbours (the surface's own neighbourhood), which, once closer than r, may come as
// near as `close` (or, starting nearer, no nearer).
inline double term_radius(double r, double d0, double close = 0) {
  if (d0 >= r) return r;
  return d0 > close && close > 0 ? close : d0 * (1 - 1e-9);
}

// The side of the line where a term can shrink: the sign of t, 0 for neither, `either` when not known.
inline constexpr int either = 2;
inline int side_of(double t) { return t > 0 ? 1 : t < 0 ? -1 : 0; }

// Narrows `reach` by one term whose value where the point starts is d0 and whose set of t below radius rho
// is set_for(rho). Every term changes by at most |t| (the points of the new pieces move no faster than the
// split point), so it cannot act before |t| = d0 - rho, nor before `after`, and only on side `toward`. A
// side already stopped before the term could act is left alone without solving for the set.
template <class SetFor>
void term(Reach& reach, double r, double d0, int toward, double after, SetFor set_for, double close = 0) {
  const double rho = term_radius(r, d0, close);
  if (!(rho > 0)) {  // already touching: no move can be trusted
    reach.positive = reach.negative = 0;
    return;
  }
  const double first = std::max(d0 - rho, after);
  const bool positive = toward == 1 || toward == either, negative = toward == -1 || toward == either;
  if ((positive && reach.positive > first) || (negative && reach.negative > first)) reach.block(set_for(rho));
}

// The move a split makes: to the side that reaches farther (the positive one unless the negative reaches
// farther by more than one part in 10^9), a rounding short of its limit so that the radius still holds once
// the point is stored.
inline double chosen_move(const Reach& limits) {
  const double t = limits.negative > limits.positive * (1 + 1e-9) ? -limits.negative : limits.positive;
  if (!std::isfinite(t))
    throw Error("a split found nothing to stop its point (a fault in selfsim: please report the recipe)");
  return t * (1 - 1e-9);
}

// Refuses a last level's radius (`radius` times `factor` for each level after the first, in coordinates
// scaled by `scale` to a region of size about 1) below `floor`: the limits would drown in rounding.
inline void check_last_radius(double radius, double factor, int levels, double scale, double floor) {
  const double last = radius * std::pow(factor, std::max(levels - 1, 0)) * scale;
  if (levels > 0 && !(last >= floor))
    throw Error("option 'radius' falls to " + number_text(last / scale) + " at level " + std::to_string(levels) +
                " (factor " + number_text(factor) + "), below " + number_text(floor) +
                " of the region's size: raise 'radius' or 'factor', or lower 'levels'");
}

}  // namespace selfsim::exclusion
