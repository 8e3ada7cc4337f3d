#include "kernels/print/wall_rays.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "kernels/base/error.h"

namespace selfsim::print {

namespace {

constexpr std::size_t chunk = 1024;

// Marches the rays of points [begin, end) in direction sign·n, all together a step at a time (so each step
// is one batched call of the distance), and writes into `out` how far each went before it crossed the
// surface again (the cap if it did not).
void march(std::span<const Vec3> points, std::span<const Vec3> normals, const Clearance& clearance, double step,
           double cap, double sign, std::size_t begin, std::size_t end, std::span<double> out) {
  // Inwards (sign −1 along n) the ray starts inside and ends at a sample outside (distance ≤ 0); outwards
  // it starts outside and ends inside (distance > 0). `side` is +1 inwards: side·distance > 0 while the ray
  // is still in the medium it started in.
  const double side = sign < 0 ? 1 : -1;
  struct Ray {
    std::size_t i;
    double t = 0, last = 0;  // how far it has gone, and side·distance there (0 at the surface itself)
  };
  std::vector<Ray> active;
  for (std::size_t i = begin; i < end; ++i) {
    out[i] = cap;
    if (normals[i] != Vec3{}) active.push_back({i});
  }
  std::vector<Vec3> at;
  std::vector<double> value, next;
  while (!active.empty()) {
    // Nothing is nearer than the distance read, less the grid's error (under two steps, a voxel): a ray far
    // from any surface leaps (sphere tracing), one near a surface goes a step at a time.
    at.resize(active.size());
    value.resize(active.size());
    next.resize(active.size());
    for (std::size_t j = 0; j < active.size(); ++j) {
      next[j] = std::min(cap, active[j].t + std::max(step, active[j].last - 2 * step));
      at[j] = points[active[j].i] + (sign * next[j]) * normals[active[j].i];
    }
    clearance(at, value);
    std::size_t kept = 0;
    for (std::size_t j = 0; j < active.size(); ++j) {
      const Ray& r = active[j];
      const double d = side * value[j];
      if (d <= 0) {
        // Crossed between the previous sample and this one: where the distance, taken as linear, is zero.
        // Crossed within the first step (the surface's own value is taken as 0): half a step, as near as the
        // samples tell.
        out[r.i] = std::min(cap, r.last > 0 ? r.t + (next[j] - r.t) * r.last / (r.last - d) : 0.5 * next[j]);
        continue;
      }
      if (next[j] >= cap) continue;  // no crossing within the cap
      active[kept++] = {r.i, next[j], d};
    }
    active.resize(kept);
  }
}

// Keeps only the crossings through a surface facing the ray's start: the far side of a wall runs roughly
// parallel to the near side (its outward normal along the ray, within acos(facing)), and across a gap the
// other part faces back. A crossing at a steep angle is the other side of a groove or a wedge meeting the
// ray's side (a V-shaped crease of a crumpled surface, whose bottom a printer fills anyway): read as the cap.
// The surface's normal at the crossing is the distance's gradient there (central differences a step wide).
// A wall crossed within the first step is kept: the grid does not resolve the normal of so thin a wall.
// A gap crossed within the first step is tested like any other: at the bottom of a crease the ray enters
// the other flank at once, at its angle, while two parts nearly touching face each other there too.
void keep_facing(std::span<const Vec3> points, std::span<const Vec3> normals, const Clearance& clearance,
                 const RayLimits& limits, double cap, double sign, std::size_t begin, std::size_t end,
                 std::span<double> out) {
  const double facing = sign < 0 ? limits.wall_facing : limits.gap_facing;
  std::vector<std::size_t> crossed;
  std::vector<Vec3> at;
  const double h = limits.step;
  const Vec3 axes[3] = {{h, 0, 0}, {0, h, 0}, {0, 0, h}};
  for (std::size_t i = begin; i < end; ++i) {
    if (!(out[i] < cap) || (sign < 0 && out[i] <= limits.step)) continue;
    crossed.push_back(i);
    // Within the first step the crossing is read a step farther in, where the grid resolves the other side.
    const double at_distance = out[i] <= limits.step ? out[i] + limits.step : out[i];
    const Vec3 x = points[i] + (sign * at_distance) * normals[i];
    for (const Vec3& e : axes) {
      at.push_back(x + e);
      at.push_back(x - e);
    }
  }
  std::vector<double> value(at.size());
  if (!at.empty()) clearance(at, value);
  for (std::size_t j = 0; j < crossed.size(); ++j) {
    const double* v = &value[6 * j];
    // The clearance grows inwards: its gradient reversed is the crossed surface's outward normal.
    const Vec3 outward{v[1] - v[0], v[3] - v[2], v[5] - v[4]};
    const double length = norm(outward);
    if (!(length > 0)) continue;
    const double along = dot(outward, sign * normals[crossed[j]]) / length;  // cosine with the ray
    // Inwards the far side's outward normal points along the ray; outwards the other part's points back.
    if (sign < 0 ? along < facing : along > -facing) out[crossed[j]] = cap;
  }
}

}  // namespace

void measure_rays(std::span<const Vec3> points, std::span<const Vec3> normals, const Clearance& clearance,
                  const RayLimits& limits, std::span<double> wall, std::span<double> gap, Progress& progress) {
  if (!(limits.step > 0) || !(limits.wall_cap > 0) || !(limits.gap_cap > 0))
    throw Error("internal error: measure_rays needs a positive step and caps");
  const std::size_t n = points.size();
  const std::size_t chunks = (n + chunk - 1) / chunk;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks, 1), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t c = r.begin(); c != r.end(); ++c) {
      if (progress.cancelled()) return;
      const std::size_t begin = c * chunk, end = std::min(n, begin + chunk);
      march(points, normals, clearance, limits.step, limits.wall_cap, -1, begin, end, wall);
      march(points, normals, clearance, limits.step, limits.gap_cap, +1, begin, end, gap);
      keep_facing(points, normals, clearance, limits, limits.wall_cap, -1, begin, end, wall);
      keep_facing(points, normals, clearance, limits, limits.gap_cap, +1, begin, end, gap);
    }
  });
  if (progress.cancelled()) throw Cancelled();
}

namespace {

// The crossings of o + t·d, tmin < t <= tmax, but the point's own triangle's, by distance; facings turned to
// the solid's outward side.
void sorted_crossings(const ExactRays& how, Vec3 o, Vec3 d, std::uint32_t own, double tmax,
                      std::vector<TriangleBvh::Hit>& hits) {
  hits.clear();
  how.bvh->crossings(o, d, how.tmin, tmax, hits);
  std::erase_if(hits, [own](const TriangleBvh::Hit& h) { return h.face == own; });
  for (TriangleBvh::Hit& h : hits) h.facing *= how.orientation;
  std::sort(hits.begin(), hits.end(), [](const auto& a, const auto& b) { return a.t < b.t; });
}

// The crossings of one point's two rays, from those of the line through it (t along -d): inwards (along -d,
// t > tmin) into `in`, outwards (along d) into `out` with t and facing turned round, each by distance, facings
// turned to the solid's outward side, the point's own triangle left out.
void split_ways(const ExactRays& how, std::span<const TriangleBvh::Hit> line, std::uint32_t own,
                std::vector<TriangleBvh::Hit>& in, std::vector<TriangleBvh::Hit>& out) {
  in.clear();
  out.clear();
  for (const TriangleBvh::Hit& h : line) {
    if (h.face == own) continue;
    if (h.t > how.tmin) in.push_back({h.t, h.face, h.facing * how.orientation});
    if (h.t < -how.tmin) out.push_back({-h.t, h.face, -h.facing * how.orientation});
  }
  const auto by_t = [](const auto& a, const auto& b) { return a.t < b.t; };
  std::sort(in.begin(), in.end(), by_t);
  std::sort(out.begin(), out.end(), by_t);
}

// Calls step(t, change, facing) for each place along the sorted hits: change +1 into the solid, -1 out of it,
// facing the mean cosine of the triangles that made the change; until step returns true.
template <class Step>
void places(const std::vector<TriangleBvh::Hit>& hits, double tolerance, const Step& step) {
  for (std::size_t i = 0; i < hits.size();) {
    // The crossings at this distance: one place on the surface (an edge or vertex reports each triangle
    // there). More entering than leaving is one step in, more leaving one step out, as many a graze.
    std::size_t j = i, in = 0, out = 0;
    double in_facing = 0, out_facing = 0;
    for (; j < hits.size() && hits[j].t - hits[i].t <= tolerance; ++j)
      if (hits[j].facing < 0) {
        ++in;
        in_facing += hits[j].facing;
      } else {
        ++out;
        out_facing += hits[j].facing;
      }
    const double t = hits[i].t;
    i = j;
    if (in == out) continue;
    if (in > out ? step(t, 1, in_facing / static_cast<double>(in)) : step(t, -1, out_facing / static_cast<double>(out)))
      return;
  }
}

// One exact reading along a ray, from its sorted crossings, the winding number `winding` before them: where
// it first reaches 0 (a wall, start 1) or rises above 0 (a gap, start 0), the crossing's distance, or the
// cap when the triangles crossed there do not face the ray as `facing` asks; nothing when these crossings
// do not get there (`winding` is then the number after them).
std::optional<double> scan(const std::vector<TriangleBvh::Hit>& hits, double tolerance, double cap, int start,
                           double facing, int& winding) {
  std::optional<double> out;
  places(hits, tolerance, [&](double t, int change, double cosine) {
    winding += change;
    if (start == 1 && winding == 0)  // out of the solid: the far side of the wall, facing along the ray
      out = cosine >= facing ? t : cap;
    if (start == 0 && winding == 1)  // into the solid: another part, facing back
      out = -cosine >= facing ? t : cap;
    return out.has_value();
  });
  return out;
}

double exact_reading(const std::vector<TriangleBvh::Hit>& hits, double tolerance, double cap, int start,
                     double facing) {
  int winding = start;
  return scan(hits, tolerance, cap, start, facing, winding).value_or(cap);
}

// The same reading for a ray through many triangles within its cap (a solid in model units, 3 mm across,
// whose sheets lie hundredths of a millimetre apart): its crossings asked for over stretches growing from a
// 64th of the cap, four times longer each, until one tells.
double reading_by_stretches(const ExactRays& how, Vec3 o, Vec3 d, std::uint32_t own, double cap, int start,
                            double facing, std::vector<TriangleBvh::Hit>& hits) {
  int winding = start;
  for (double from = how.tmin, to = cap / 64;; from = to, to = std::min(cap, 4 * to)) {
    hits.clear();
    how.bvh->crossings(std::span<const Vec3>(&o, 1), d, from, to, hits);
    std::erase_if(hits, [own](const TriangleBvh::Hit& h) { return h.face == own; });
    for (TriangleBvh::Hit& h : hits) h.facing *= how.orientation;
    std::sort(hits.begin(), hits.end(), [](const auto& a, const auto& b) { return a.t < b.t; });
    if (const std::optional<double> found = scan(hits, how.tmin, cap, start, facing, winding)) return *found;
    if (to >= cap) return cap;
  }
}

// The winding number just outside a face at o (outward d): what the crossings out to `far` leave behind.
int outside_winding(const ExactRays& how, Vec3 o, Vec3 d, std::uint32_t own, std::vector<TriangleBvh::Hit>& hits) {
  sorted_crossings(how, o, d, own, how.far, hits);
  int winding = 0;  // far away: outside; each way out of the solid met going there was a way into it before
  places(hits, how.tmin, [&](double, int change, double) {
    winding -= change;
    return false;
  });
  return winding;
}

}  // namespace

void measure_rays_exact(std::span<const Vec3> points, std::span<const Vec3> normals, const ExactRays& how,
                        const RayLimits& limits, std::span<double> wall, std::span<double> gap, Progress& progress) {
  if (how.bvh == nullptr || !(limits.wall_cap > 0) || !(limits.gap_cap > 0) || !(how.tmin >= 0) ||
      how.faces.size() != points.size() || !(how.may_be_buried.empty() || how.may_be_buried.size() == points.size()))
    throw Error("internal error: measure_rays_exact needs a tree, positive caps and a face for each point");
  const std::size_t n = points.size();
  const std::size_t chunks = (n + chunk - 1) / chunk;
  // The points of one triangle (consecutive, one normal) go through the tree together, up to `packet` at
  // a time (a coarse face's thousands would make too thick a ray).
  constexpr std::size_t packet = 16;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks, 1), [&](const tbb::blocked_range<std::size_t>& r) {
    std::vector<TriangleBvh::Hit> hits, in, out;
    for (std::size_t c = r.begin(); c != r.end(); ++c) {
      if (progress.cancelled()) return;
      const std::size_t end = std::min(n, (c + 1) * chunk);
      // After a packet through many sheets the next 15 (neighbours: points come face by face) go straight to
      // stretches; then one tries whole lines again.
      int dense = 0;
      for (std::size_t i = c * chunk; i < end;) {
        const std::uint32_t own = how.faces[i];
        const Vec3 d = normals[i];
        std::size_t j = i + 1;
        while (j < end && j - i < packet && how.faces[j] == own && normals[j] == d) ++j;
        hits.clear();
        // Past 256 boxes and crossings (a printable solid's rays take about 60 and 10): rays through many
        // sheets, read by stretches.
        const bool all = d == Vec3{} || (dense == 0 && how.bvh->crossings(points.subspan(i, j - i), -1.0 * d,
                                                                          -limits.gap_cap, limits.wall_cap, hits, 256));
        dense = all ? 0 : dense > 0 ? dense - 1 : 15;
        std::sort(hits.begin(), hits.end(), [](const auto& a, const auto& b) { return a.ray < b.ray; });
        auto first = hits.begin();
        for (std::size_t k = i; k < j; ++k) {
          auto last = first;
          while (last != hits.end() && last->ray == k - i) ++last;
          const std::span<const TriangleBvh::Hit> line(first, last);
          first = last;
          if (d == Vec3{}) {
            wall[k] = limits.wall_cap;
            gap[k] = limits.gap_cap;
            continue;
          }
          if (!all) {
            wall[k] = reading_by_stretches(how, points[k], -1.0 * d, own, limits.wall_cap, 1, limits.wall_facing, in);
            gap[k] = reading_by_stretches(how, points[k], d, own, limits.gap_cap, 0, limits.gap_facing, in);
          } else {
            split_ways(how, line, own, in, out);
            wall[k] = exact_reading(in, how.tmin, limits.wall_cap, 1, limits.wall_facing);
            gap[k] = exact_reading(out, how.tmin, limits.gap_cap, 0, limits.gap_facing);
          }
          // A buried point reads both caps: tested (a ray out of the solid's box) only where it read less.
          const bool capped = !(wall[k] < limits.wall_cap) && !(gap[k] < limits.gap_cap);
          if (!capped && !how.may_be_buried.empty() && how.may_be_buried[k] &&
              outside_winding(how, points[k], d, own, in) > 0) {
            wall[k] = limits.wall_cap;
            gap[k] = limits.gap_cap;
          }
        }
        i = j;
      }
    }
  });
  if (progress.cancelled()) throw Cancelled();
}

}  // namespace selfsim::print
