#include "kernels/exclusion/exclusion_surface.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <optional>
#include <string>

#include "kernels/base/check.h"
#include "kernels/exclusion/surface_net.h"
#include "kernels/geom/box_grid3.h"
#include "kernels/geom/distance3.h"
#include "kernels/geom/mesh_check.h"
#include "kernels/geom/mesh_intersections.h"
#include "kernels/geom/winding_number.h"

namespace selfsim::exclusion {

namespace {

struct Counts {
  double points, edges, triangles;
};

// A triangle mesh after `levels` splits 1 -> 4: every edge adds a point and becomes two edges, every
// triangle adds three edges inside.
Counts grown(Counts c, int levels) {
  for (int l = 0; l < levels; ++l) c = {c.points + c.edges, 2 * c.edges + 3 * c.triangles, 4 * c.triangles};
  return c;
}

Counts counts(const Mesh& start) {
  const MeshTopology t = mesh_topology(start);
  return {static_cast<double>(start.points.size()), static_cast<double>(t.edges), static_cast<double>(t.faces)};
}

// Working memory, in budget points of 16 bytes: a point's coordinates and level, and about 260 bytes a
// triangle (its corners and surface, grid entries, and while a level is split its half edges, midpoints and
// fans); the neighbourhood rule adds about 100 (each vertex's edges with their lengths, the search's marks
// per thread). Measured at 10 levels: 327 MiB peak for the neighbourhood rule, 232 MiB for the strict one.
double working_points_per_triangle(SurfaceRule rule) { return rule == SurfaceRule::neighbourhood ? 22 : 16; }

// The region and start moved to the origin and scaled by a power of two to a size about 1: the closed-form
// limits take coordinates to the fourth power and more.
struct Normalised {
  Vec3 centre;
  double scale;
  Vec3 to(Vec3 p) const { return scale * (p - centre); }
  Vec3 from(Vec3 q) const { return (1 / scale) * q + centre; }
};

Mesh moved(const Mesh& m, const Normalised& n) {
  Mesh out;
  out.triangles = m.triangles;
  out.points.reserve(m.points.size());
  for (Vec3 p : m.points) out.points.push_back(n.to(p));
  return out;
}

double since(std::chrono::steady_clock::time_point from) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - from).count();
}

// The start must be a manifold of triangles with area, strictly inside the region, touching neither
// itself nor the boundary.
void check_start(const Mesh& boundary, const Mesh& start, Progress& progress) {
  if (start.triangles.empty()) throw Error("the start has no triangles");
  const MeshTopology t = mesh_topology(start);
  if (!t.manifold()) throw Error("the start is not a manifold surface: " + t.first_problem);
  // Two triangles on the same three points pass as neighbours along every edge, and lie on each other.
  std::vector<std::pair<Triangle, std::size_t>> sorted;
  for (std::size_t i = 0; i < start.triangles.size(); ++i) {
    Triangle c = start.triangles[i];
    std::sort(c.begin(), c.end());
    sorted.push_back({c, i});
  }
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 1; i < sorted.size(); ++i)
    if (sorted[i].first == sorted[i - 1].first)
      throw Error("start triangles " + std::to_string(sorted[i - 1].second + 1) + " and " +
                  std::to_string(sorted[i].second + 1) + " lie on the same three points");
  for (std::size_t i = 0; i < start.triangles.size(); ++i) {
    const Triangle& c = start.triangles[i];
    const Vec3 n = cross(start.points[c[1]] - start.points[c[0]], start.points[c[2]] - start.points[c[0]]);
    const double longest =
        std::max({norm(start.points[c[1]] - start.points[c[0]]), norm(start.points[c[2]] - start.points[c[1]]),
                  norm(start.points[c[0]] - start.points[c[2]])});
    if (!(norm(n) > 1e-12 * longest * longest)) throw Error("start triangle " + std::to_string(i + 1) + " has no area");
  }
  for (std::size_t i = 0; i < start.points.size(); ++i)
    if (winding_number(boundary, start.points[i]) < 0.5)
      throw Error("start point " + std::to_string(i + 1) + " lies outside the region");
  Mesh both = start;
  const auto offset = static_cast<std::uint32_t>(start.points.size());
  both.points.insert(both.points.end(), boundary.points.begin(), boundary.points.end());
  for (Triangle c : boundary.triangles) both.triangles.push_back({c[0] + offset, c[1] + offset, c[2] + offset});
  if (const auto pair = first_intersection(both, progress)) {
    const std::size_t n = start.triangles.size();
    if (pair->second < n)
      throw Error("start triangles " + std::to_string(pair->first + 1) + " and " + std::to_string(pair->second + 1) +
                  " cross or touch");
    if (pair->first < n)
      throw Error("start triangle " + std::to_string(pair->first + 1) + " crosses or touches the region's boundary");
  }
}

// The start's gaps below radius r to the walls and between its surfaces (`surface`: each start triangle's),
// found through a grid of the triangles' boxes.
StartGaps start_gaps(const Mesh& boundary, const Mesh& start, const std::vector<std::int32_t>& surface, double r,
                     Progress& progress) {
  auto corners = [](const Mesh& m, std::size_t t) {
    const Triangle& c = m.triangles[t];
    return std::array<Vec3, 3>{m.points[c[0]], m.points[c[1]], m.points[c[2]]};
  };
  auto box_of = [](const std::array<Vec3, 3>& c, double grow) {
    BBox3 b;
    for (Vec3 p : c) b.add(p);
    return BBox3{b.min - Vec3::all(grow), b.max + Vec3::all(grow)};
  };
  constexpr std::uint32_t wall_bit = 0x80000000u;
  BoxGrid3 grid(boundary.bbox(), r);
  for (std::uint32_t t = 0; t < boundary.triangles.size(); ++t)
    grid.insert(wall_bit | t, box_of(corners(boundary, t), 0));
  for (std::uint32_t t = 0; t < start.triangles.size(); ++t) grid.insert(t, box_of(corners(start, t), 0));
  StartGaps gaps;
  std::vector<std::pair<double, std::uint32_t>> near;  // box gap, id
  for (std::uint32_t t = 0; t < start.triangles.size(); ++t) {
    if (progress.cancelled()) throw Cancelled();
    const std::array<Vec3, 3> a = corners(start, t);
    const BBox3 own = box_of(a, 0);
    near.clear();
    grid.visit(box_of(a, r), [&](std::uint32_t id) {
      const bool wall = id & wall_bit;
      if (!wall && (id <= t || surface[id] == surface[t])) return;
      const BBox3 other = box_of(corners(wall ? boundary : start, id & ~wall_bit), 0);
      near.push_back({norm(max_each(max_each(own.min - other.max, other.min - own.max), Vec3{})), id});
    });
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    // Nearest boxes first: once a box is farther than the least gap found (or the radius), so is the rest.
    double wall_best = r, between_best = r;
    for (const auto& [box_gap, id] : near) {
      const bool wall = id & wall_bit;
      if (box_gap >= std::max(wall_best, between_best)) break;
      if (box_gap >= (wall ? wall_best : between_best)) continue;
      const double d = triangle_distance(a, corners(wall ? boundary : start, id & ~wall_bit));
      (wall ? wall_best : between_best) = std::min(wall ? wall_best : between_best, d);
      if (d >= r * (1 - 1e-9)) continue;  // a start at the radius (to rounding) keeps it
      if (wall && d < gaps.wall) gaps.wall = d, gaps.wall_triangle = t;
      if (!wall && d < gaps.between) gaps.between = d, gaps.first = t, gaps.second = id;
    }
  }
  return gaps;
}

}  // namespace

void SurfaceOptions::validate() const {
  check_between(radius, 1e-300, 1e300, "option 'radius'");
  if (!(factor > 0 && factor <= 1)) throw Error("option 'factor' must be in (0, 1], got " + number_text(factor));
  check_range(levels, 0, 20, "option 'levels'");
  if (!(neighbourhood > 0 && (neighbourhood <= 1000 || std::isinf(neighbourhood))))
    throw Error("option 'neighbourhood' must be in (0, 1000] radii or math.huge (the whole surface), got " +
                number_text(neighbourhood));
  if (!(near >= 1e-6 && near < 1)) throw Error("option 'near' must be in [1e-6, 1) radii, got " + number_text(near));
}

double surface_size(const Mesh& start, int levels, bool keep_levels, SurfaceRule rule) {
  const Counts c = grown(counts(start), levels);
  double kept = 0;
  for (int l = 0; keep_levels && l < levels; ++l) {
    const Counts step = grown(counts(start), l);
    kept += step.points + step.triangles;
  }
  return c.points + working_points_per_triangle(rule) * c.triangles + kept;
}

SurfaceResult exclusion_surface(const Mesh& boundary, const Mesh& start, const SurfaceOptions& opt, Progress& progress,
                                const WallGrid* walls) {
  opt.validate();
  start.validate();
  boundary.validate();
  const Counts final_counts = grown(counts(start), opt.levels);
  check_budget(surface_size(start, opt.levels, opt.keep_levels, opt.rule), opt.budget,
               "levels = " + std::to_string(opt.levels) + " (" + count_text(final_counts.triangles) +
                   " triangles, each " + count_text(working_points_per_triangle(opt.rule)) +
                   " budget points with its working memory)");
  const MeshTopology region = mesh_topology(boundary);
  if (!region.closed()) throw Error("the region's boundary is not a closed surface: " + region.first_problem);
  if (const auto pair = first_intersection(boundary, progress))
    throw Error("the region's boundary crosses itself (its triangles " + std::to_string(pair->first + 1) + " and " +
                std::to_string(pair->second + 1) + ")");
  const BBox3 box = boundary.bbox();
  const double side = std::max({box.size().x, box.size().y, box.size().z});
  const Normalised n{0.5 * (box.min + box.max), std::ldexp(1.0, -std::ilogb(side))};
  const Mesh local_boundary = moved(boundary, n), local_start = moved(start, n);
  check_start(local_boundary, local_start, progress);
  check_last_radius(opt.radius, opt.factor, opt.levels, n.scale, 1e-9);
  // The points go back to the caller's coordinates in double precision: far from the origin their rounding
  // would eat the radius.
  const double far = std::max({std::abs(box.min.x), std::abs(box.min.y), std::abs(box.min.z), std::abs(box.max.x),
                               std::abs(box.max.y), std::abs(box.max.z)});
  const double last = opt.radius * std::pow(opt.factor, std::max(opt.levels - 1, 0));
  if (!(far * 1e-12 < last))
    throw Error("the region lies " + number_text(far) + " from the origin, too far for the last radius " +
                number_text(last) + " in double precision: move it nearer the origin");

  Surfaces s(local_boundary, local_start, final_counts.points, final_counts.triangles);
  const std::optional<WallGrid> local_walls =
      walls ? std::optional<WallGrid>(walls->in_frame(n.centre, n.scale)) : std::nullopt;
  if (local_walls) s.set_walls(&*local_walls);
  SurfaceResult result;
  if (opt.rule == SurfaceRule::neighbourhood) s.set_neighbourhood(opt.neighbourhood, opt.near);
  result.start_gaps = start_gaps(local_boundary, local_start, s.surfaces(), opt.radius * n.scale, progress);
  result.start_gaps.wall /= n.scale, result.start_gaps.between /= n.scale;
  // In the caller's coordinates, the start points exactly as given.
  auto in_place = [&](Mesh m) {
    for (std::size_t i = 0; i < m.points.size(); ++i)
      m.points[i] = i < start.points.size() ? start.points[i] : n.from(m.points[i]);
    if (!m.finite()) throw Error("the exclusion surface has non-finite points");
    return m;
  };
  double r = opt.radius * n.scale;
  for (int level = 1; level <= opt.levels; ++level, r *= opt.factor) {
    const auto begun = std::chrono::steady_clock::now();
    const double triangles = static_cast<double>(local_start.triangles.size()) * std::pow(4.0, level);
    progress.start(
        ("surface " + std::to_string(level) + "/" + std::to_string(opt.levels) + " " + count_text(triangles) + " tri")
            .c_str());
    progress.step(0);
    LevelReport report;
    if (opt.keep_levels) result.steps.push_back(in_place(s.result()));
    s.subdivide(level, r);
    s.grow(r, report, progress);
    report.area = s.area() / (n.scale * n.scale);
    report.seconds = since(begun);
    result.levels.push_back(report);
  }
  result.surface = in_place(s.result());
  // What a print may rely on (solid.thicken): after level k pieces once apart keep that level's radius (the
  // start is meant to keep the first), or the gap between start surfaces that began nearer. On every step,
  // so a growth series carries the same fields throughout.
  const auto mark = [&](Mesh& m, int level) {
    const double r = opt.radius * std::pow(opt.factor, std::max(level, 1) - 1);
    const double gap = result.start_gaps.between;
    m.face_fields.set(Field{"clearance", 1, std::vector<double>{std::isfinite(gap) ? std::min(r, gap) : r}, true});
  };
  for (std::size_t k = 0; k < result.steps.size(); ++k) mark(result.steps[k], static_cast<int>(k));
  mark(result.surface, opt.levels);
  return result;
}

}  // namespace selfsim::exclusion
