#include "kernels/print/print_samples.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>

#include "kernels/print/sharp_edges.h"

namespace selfsim::print {

namespace {

double squared(Vec3 v) { return dot(v, v); }

Vec3 incentre(Vec3 a, Vec3 b, Vec3 c) {
  const double la = std::sqrt(squared(c - b)), lb = std::sqrt(squared(a - c)), lc = std::sqrt(squared(b - a));
  const double sum = la + lb + lc;
  return sum > 0 ? (1 / sum) * (la * a + lb * b + lc * c) : a;
}

// The halves of triangle abc (longest-edge bisection, which keeps their shapes: no slivers from slivers)
// down to `spacing`, each one's incentre passed to `take` with its share of the area (halves halve it).
// Squared lengths: the same order and comparisons as lengths, without a square root each.
template <class Take>
void halves(Vec3 a, Vec3 b, Vec3 c, double share, double spacing, const Take& take) {
  const double ab = squared(b - a), bc = squared(c - b), ca = squared(a - c);
  const double longest = std::max({ab, bc, ca});
  if (!(longest > spacing * spacing) || !std::isfinite(longest)) {
    take(incentre(a, b, c), share);
    return;
  }
  // Rotate so that ab is the longest edge, then split it at its midpoint m.
  if (ab < longest && bc == longest) return halves(b, c, a, share, spacing, take);
  if (ab < longest) return halves(c, a, b, share, spacing, take);
  const Vec3 m = 0.5 * (a + b);
  halves(a, m, c, 0.5 * share, spacing, take);
  halves(m, b, c, 0.5 * share, spacing, take);
}

// How many halves of abc sampling down to `spacing` makes: exactly, or some number over `limit` once the
// count passes it (counting no further).
double count_halves(Vec3 a, Vec3 b, Vec3 c, double spacing, double limit) {
  const double ab = squared(b - a), bc = squared(c - b), ca = squared(a - c);
  const double longest = std::max({ab, bc, ca});
  if (!(longest > spacing * spacing) || !std::isfinite(longest)) return 1;
  if (limit < 2) return 2;  // halved: two at least
  if (ab < longest && bc == longest) return count_halves(b, c, a, spacing, limit);
  if (ab < longest) return count_halves(c, a, b, spacing, limit);
  const Vec3 m = 0.5 * (a + b);
  const double first = count_halves(a, m, c, spacing, limit - 1);  // the other half takes one at least
  if (first > limit - 1) return first + 1;
  return first + count_halves(m, b, c, spacing, limit - first);
}

constexpr int rungs = 8;
using Ladder = std::array<double, rungs>;

// counts[k] += how many halves of abc sampling down to spacing[k] makes, for every k < top (spacings
// ascending): one bisection, down to the finest. A half is whole for every rung from the first its
// longest edge fits; only the finer rungs split it further.
void count_ladder(Vec3 a, Vec3 b, Vec3 c, const Ladder& squares, int top, Ladder& counts) {
  const double ab = squared(b - a), bc = squared(c - b), ca = squared(a - c);
  const double longest = std::max({ab, bc, ca});
  int whole = 0;
  while (whole < top && longest > squares[whole] && std::isfinite(longest)) ++whole;
  for (int k = whole; k < top; ++k) counts[k] += 1;
  if (whole == 0) return;
  if (ab < longest && bc == longest) return count_ladder(b, c, a, squares, whole, counts);
  if (ab < longest) return count_ladder(c, a, b, squares, whole, counts);
  const Vec3 m = 0.5 * (a + b);
  count_ladder(a, m, c, squares, whole, counts);
  count_ladder(m, b, c, squares, whole, counts);
}

// lower[k] += at least how many halves of abc sampling down to spacing[k] makes, for every k, without
// halving: one where its longest edge fits; else two at least, and at least its area over the most a half
// whose longest edge fits holds (an equilateral one's, sqrt(3)/4 s², taken a little larger against
// rounding), a whole number. A rung whose bound passes the budget cannot fit and need not be counted.
void lower_ladder(Vec3 a, Vec3 b, Vec3 c, const Ladder& squares, Ladder& lower) {
  const double longest = std::max({squared(b - a), squared(c - b), squared(a - c)});
  const double area = 0.5 * norm(cross(b - a, c - a));
  for (int k = 0; k < rungs; ++k)
    lower[k] += !(longest > squares[k]) || !std::isfinite(longest) || !std::isfinite(area)
                    ? 1
                    : std::max(2.0, std::ceil(area / (0.4331 * squares[k])));
}

SamplePlan plan_of(double spacing, const std::vector<double>& per_run) {
  SamplePlan p;
  p.spacing = spacing;
  p.starts.assign(1, 0);
  for (double n : per_run) p.starts.push_back(p.starts.back() + static_cast<std::size_t>(n));
  return p;
}

}  // namespace

SamplePlan plan_samples(const Mesh& m, double finest, double area, double most, Progress& progress) {
  const std::size_t runs = (m.faces() + sample_run - 1) / sample_run;
  const auto corners = [&](std::size_t f) {
    const Triangle& t = m.triangles[f];
    return std::array<Vec3, 3>{m.points[t[0]], m.points[t[1]], m.points[t[2]]};
  };
  // At `finest`, all runs adding to one total and stopping once it passes `most`; not counted where the
  // area alone says it would (the ladder's first rung is then finer than `finest`).
  const double bound = std::sqrt(area / (0.433 * most));
  std::vector<double> per_run(runs, 0);
  std::atomic<double> total{bound > finest ? most + 1 : 0};
  tbb::parallel_for(std::size_t(0), runs, [&](std::size_t run) {
    if (progress.cancelled() || total.load() > most) return;
    double n = 0;
    for (std::size_t f = run * sample_run; f < std::min(m.faces(), (run + 1) * sample_run); ++f) {
      if (f % 1024 == 0 && total.load(std::memory_order_relaxed) + n > most) break;
      const auto [a, b, c] = corners(f);
      n += count_halves(a, b, c, finest, most - n);
      if (n > most) break;
    }
    per_run[run] = n;
    double seen = total.load();
    while (!total.compare_exchange_weak(seen, seen + n)) {
    }
  });
  if (progress.cancelled()) throw Cancelled();
  if (total.load() <= most) return plan_of(finest, per_run);
  // Too many: the ladder from the area's bound up, eight rungs a pass, until one fits. The rungs that surely
  // make too many (lower_ladder) are passed over first: the count then halves no finer than the first rung
  // that may fit (on a level-11 dragon, 1.4 million halves instead of 2.2 million).
  double spacing = std::max(finest, bound);
  const auto ladder_from = [](double first, Ladder& spacings, Ladder& squares) {
    for (int k = 0; k < rungs; ++k) {
      spacings[k] = first;
      squares[k] = first * first;
      first *= 1.25;
    }
    return first;
  };
  for (;;) {
    Ladder spacings, squares;
    const double next = ladder_from(spacing, spacings, squares);
    std::vector<Ladder> lower(runs, Ladder{});
    tbb::parallel_for(std::size_t(0), runs, [&](std::size_t run) {
      if (progress.cancelled()) return;
      for (std::size_t f = run * sample_run; f < std::min(m.faces(), (run + 1) * sample_run); ++f) {
        const auto [a, b, c] = corners(f);
        lower_ladder(a, b, c, squares, lower[run]);
      }
    });
    if (progress.cancelled()) throw Cancelled();
    int first = 0;
    while (first < rungs) {
      double sum = 0;
      for (const Ladder& l : lower) sum += l[first];
      if (!(sum > most)) break;
      ++first;
    }
    if (first == rungs) {
      spacing = next;
      continue;
    }
    spacing = spacings[first];
    break;
  }
  for (;;) {
    Ladder spacings, squares;
    spacing = ladder_from(spacing, spacings, squares);
    std::vector<Ladder> counts(runs, Ladder{});
    tbb::parallel_for(std::size_t(0), runs, [&](std::size_t run) {
      if (progress.cancelled()) return;
      for (std::size_t f = run * sample_run; f < std::min(m.faces(), (run + 1) * sample_run); ++f) {
        const auto [a, b, c] = corners(f);
        count_ladder(a, b, c, squares, rungs, counts[run]);
      }
    });
    if (progress.cancelled()) throw Cancelled();
    for (int k = 0; k < rungs; ++k) {
      double sum = 0;
      for (const Ladder& l : counts) sum += l[k];
      if (sum > most) continue;
      for (std::size_t run = 0; run < runs; ++run) per_run[run] = counts[run][k];
      return plan_of(spacings[k], per_run);
    }
  }
}

Samples samples_of(const Mesh& m, bool inward, const SamplePlan& plan) {
  Samples s;
  const std::size_t n = plan.count();
  s.points.resize(n);
  s.normals.resize(n);
  s.face.resize(n);
  s.area.resize(n);
  const double flip = inward ? -1 : 1;
  tbb::parallel_for(std::size_t(0), plan.starts.size() - 1, [&](std::size_t run) {
    std::size_t at = plan.starts[run];
    for (std::size_t f = run * sample_run; f < std::min(m.faces(), (run + 1) * sample_run); ++f) {
      const Triangle& t = m.triangles[f];
      const Vec3 nf = area_normal(m, t);
      const double length = norm(nf);
      const Vec3 normal = length > 0 && std::isfinite(length) ? (flip / length) * nf : Vec3{};
      halves(m.points[t[0]], m.points[t[1]], m.points[t[2]], 0.5 * length, plan.spacing, [&](Vec3 p, double area) {
        s.points[at] = p;
        s.normals[at] = normal;
        s.face[at] = static_cast<std::uint32_t>(f);
        s.area[at] = area;
        ++at;
      });
    }
  });
  return s;
}

void clear_of_edges(const Mesh& m, Samples& s, double inset) {
  const SharpEdges edges(m, 2 * inset);
  std::vector<double> clear(s.points.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, clear.size(), 4096),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i) clear[i] = edges.distance(s.points[i]);
                    });
  std::vector<double> farthest(edges.patch_count(), 0);
  for (std::size_t i = 0; i < clear.size(); ++i) {
    double& f = farthest[edges.patches()[s.face[i]]];
    f = std::max(f, clear[i]);
  }
  // Kept in place, in order (a triangle's points stay consecutive): no second copy of the points.
  std::size_t kept = 0;
  for (std::size_t i = 0; i < clear.size(); ++i) {
    if (clear[i] < std::min(inset, 0.5 * farthest[edges.patches()[s.face[i]]])) continue;
    s.points[kept] = s.points[i];
    s.normals[kept] = s.normals[i];
    s.face[kept] = s.face[i];
    s.area[kept] = s.area[i];
    ++kept;
  }
  s.points.resize(kept);
  s.normals.resize(kept);
  s.face.resize(kept);
  s.area.resize(kept);
}

}  // namespace selfsim::print
