// Sets of a line's parameter t where a quadratic or linear expression is negative or positive: what a split
// point moving along its bisector (seed 004) needs to learn where an obstacle stops it. Open intervals, at
// most a few per set; ±infinity for unbounded ends.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace selfsim::exclusion {

inline constexpr double unbounded = std::numeric_limits<double>::infinity();

struct Interval {
  double lo = unbounded, hi = -unbounded;  // empty by default
  bool empty() const { return !(lo < hi); }
};

// A union of up to four open intervals (two quadratics' sets intersected).
struct IntervalSet {
  Interval part[4];
  int count = 0;

  void add(Interval i) {
    if (!i.empty() && count < 4) part[count++] = i;
  }
  // The smallest interval holding every part (the set itself when it is known to be one interval).
  Interval hull() const {
    Interval h;
    for (int k = 0; k < count; ++k) h = {std::min(h.lo, part[k].lo), std::max(h.hi, part[k].hi)};
    return h;
  }
};

inline IntervalSet intersect(const IntervalSet& x, const IntervalSet& y) {
  IntervalSet out;
  for (int i = 0; i < x.count; ++i)
    for (int j = 0; j < y.count; ++j)
      out.add({std::max(x.part[i].lo, y.part[j].lo), std::min(x.part[i].hi, y.part[j].hi)});
  return out;
}

// The smallest interval holding the parts of x ∩ y that `keep` accepts, without listing them (they may be
// more than four). A caller whose sets come from ill-conditioned quadratics checks each part there.
template <class Keep>
Interval intersect_hull(const IntervalSet& x, const IntervalSet& y, Keep keep) {
  Interval h;
  for (int i = 0; i < x.count; ++i)
    for (int j = 0; j < y.count; ++j) {
      const Interval part{std::max(x.part[i].lo, y.part[j].lo), std::min(x.part[i].hi, y.part[j].hi)};
      if (!part.empty() && keep(part)) h = {std::min(h.lo, part.lo), std::max(h.hi, part.hi)};
    }
  return h;
}

inline Interval intersect_hull(const IntervalSet& x, const IntervalSet& y) {
  return intersect_hull(x, y, [](Interval) { return true; });
}

// A finite point of a non-empty interval: its middle, or a point a unit or more inside an unbounded end.
inline double inner_point(Interval i) {
  if (std::isfinite(i.lo) && std::isfinite(i.hi)) return 0.5 * (i.lo + i.hi);
  if (std::isfinite(i.lo)) return i.lo + std::max(1.0, std::abs(i.lo));
  if (std::isfinite(i.hi)) return i.hi - std::max(1.0, std::abs(i.hi));
  return 0;
}

// {t : g0 + g1·t > 0}.
inline IntervalSet positive_linear(double g0, double g1) {
  IntervalSet s;
  if (g1 > 0)
    s.add({-g0 / g1, unbounded});
  else if (g1 < 0)
    s.add({-unbounded, -g0 / g1});
  else if (g0 > 0)
    s.add({-unbounded, unbounded});
  return s;
}

// {t : a·t² + 2b·t + c < 0}. The roots come from the cancellation-free pair q/a, c/q, so a nearly zero
// (a nearly linear expression) still gives the finite root accurately.
inline IntervalSet negative_quadratic(double a, double b, double c) {
  if (a == 0) return positive_linear(-c, -2 * b);
  IntervalSet s;
  const double disc = b * b - a * c;
  if (!(disc > 0)) {
    if (a < 0) s.add({-unbounded, unbounded});
    return s;
  }
  const double q = -(b + std::copysign(std::sqrt(disc), b));
  const double r1 = q / a, r2 = q != 0 ? c / q : 0;
  const double lo = std::min(r1, r2), hi = std::max(r1, r2);
  if (a > 0) {
    s.add({lo, hi});
  } else {
    s.add({-unbounded, lo});
    s.add({hi, unbounded});
  }
  return s;
}

}  // namespace selfsim::exclusion
