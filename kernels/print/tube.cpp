#include "kernels/print/tube.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <string>
#include <type_traits>
#include <vector>

#include "kernels/base/check.h"
#include "kernels/base/error.h"
#include "kernels/geom/mesh_intersections.h"
#include "kernels/geom/point_text.h"

namespace selfsim::print {

namespace {

// The sharpest turn taken: the mitre stretches a ring by 1/cos(half the turn), 11.5 times at 170 degrees,
// and without bound towards 180.
constexpr double max_turn_degrees = 170;
constexpr double degrees_per_radian = 180 / std::numbers::pi;
// Progress is reported (and a stop looked for) once per this many points of the tube, never per point.
constexpr std::size_t report_points = 65536;

// "(1.5, 0, -2)": six significant digits, enough to find the place in a viewer without a wall of digits.
std::string place_text(Vec3 p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g)", p.x, p.y, p.z);
  return buf;
}

std::string angle_text(double degrees) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", degrees);
  return buf;
}

std::string count(std::size_t i) { return std::to_string(i + 1); }

// "path 2, point 7 (1, 0.5, 0)", counted from 1.
std::string at_point(std::size_t path, std::size_t point, Vec3 p) {
  return "path " + count(path) + ", point " + count(point) + " " + place_text(p);
}

// One path as the tube sees it: a closed path's last point dropped (its first ring closes the loop).
struct Path {
  std::span<const Vec3> given;   // the path's points as the curve has them
  std::span<const Vec3> points;  // the ring centres: given, less a closed path's last point
  std::span<const double> radii;
  std::size_t first = 0;  // index of points[0] in the curve
  std::size_t index = 0;  // which path of the curve
  bool closed = false;

  std::size_t rings() const { return points.size(); }
  std::size_t segments() const { return closed ? points.size() : points.size() - 1; }
  // The segment after j (a closed path's last segment is followed by its first).
  std::size_t next(std::size_t j) const { return j + 1 == points.size() ? 0 : j + 1; }
  // The segment that enters ring i (a closed path's first ring is entered by its last segment).
  std::size_t before(std::size_t i) const { return i == 0 ? points.size() - 1 : i - 1; }
  Vec3 direction(std::size_t j) const { return normalized(points[next(j)] - points[j]); }
  double length(std::size_t j) const { return norm(points[next(j)] - points[j]); }
  // True when ring i sits between two segments; otherwise it ends an open path and gets a cap.
  bool joint(std::size_t i) const { return closed || (i > 0 && i + 1 < points.size()); }
};

Path path_of(const Polyline3& c, std::span<const double> radii, std::size_t i) {
  Path v;
  v.given = c.path(i);
  v.index = i;
  v.first = c.path_begin(i);
  v.closed = closed_path3(v.given);
  v.points = v.closed ? v.given.first(v.given.size() - 1) : v.given;
  v.radii = radii.subspan(v.first, v.points.size());
  return v;
}

struct Size {
  double points = 0, triangles = 0;
};

// One ring a point (a closed path's last point has none), two cap centres on an open path; two triangles
// a ring side on every segment's wall, and an open path's two caps make up the segment it lacks.
Size path_size(std::size_t points, bool closed, int sides) {
  const double rings = static_cast<double>(closed ? points - 1 : points);
  return {rings * sides + (closed ? 0 : 2), 2.0 * sides * rings};
}

template <class V>
Size curve_size(const PolylineT<V>& c, int sides) {
  Size total;
  for (std::size_t i = 0; i < c.paths(); ++i) {
    const auto p = c.path(i);
    bool closed = false;
    if constexpr (std::is_same_v<V, Vec2>) {
      closed = closed_path(p);
    } else {
      closed = closed_path3(p);
    }
    const Size s = path_size(p.size(), closed, sides);
    total.points += s.points;
    total.triangles += s.triangles;
  }
  return total;
}

void check_curve(const Polyline3& c, std::span<const double> radii) {
  if (!c.paths_consistent()) throw Error("the curve's path ends do not match its points");
  if (c.paths() == 0) throw Error("the curve has no points to make a tube around");
  if (radii.size() != c.points.size())
    throw Error("the tube needs one radius per point: got " + std::to_string(radii.size()) + " for " +
                std::to_string(c.points.size()) + " points");
  for (std::size_t i = 0; i < c.paths(); ++i) {
    const auto p = c.path(i);
    const std::size_t first = c.path_begin(i);
    for (std::size_t j = 0; j < p.size(); ++j) {
      if (!is_finite(p[j])) throw Error(at_point(i, j, p[j]) + " is not finite");
      const double r = radii[first + j];
      if (!(r > 0) || !std::isfinite(r))
        throw Error(at_point(i, j, p[j]) + ": the radius must be a finite number > 0, got " + number_text(r));
    }
  }
  c.point_fields.check(c.points.size(), "point");
  c.cell_fields.check(c.paths(), "cell");
}

// The refusals that keep a path's tube from collapsing or folding at a joint, in the order of its points.
void check_path(const Path& v) {
  const std::string path = "path " + count(v.index);
  if (v.given.size() == 1)
    throw Error(path + " has a single point " + place_text(v.given[0]) + ": a tube needs at least one segment");
  const auto zero_length = [&](std::size_t j, Vec3 p) {
    return Error(path + ", points " + count(j) + " and " + count(j + 1) + " are both at " + place_text(p) +
                 ": a zero-length segment has no direction to make a tube along (remove the duplicate point)");
  };
  for (std::size_t j = 0; j + 1 < v.given.size(); ++j)
    if (v.given[j] == v.given[j + 1]) throw zero_length(j, v.given[j]);
  if (v.closed && v.points.back() == v.points.front()) throw zero_length(v.rings() - 1, v.points.back());
  for (std::size_t i = 0; i < v.rings(); ++i) {
    if (!v.joint(i)) continue;
    const std::size_t a = v.before(i);
    const double turn = std::acos(std::clamp(dot(v.direction(a), v.direction(i)), -1.0, 1.0));
    const std::string deg = angle_text(turn * degrees_per_radian);
    if (turn * degrees_per_radian > max_turn_degrees)
      throw Error(path + " turns by " + deg + " degrees at point " + count(i) + " " + place_text(v.points[i]) +
                  ": more than " + angle_text(max_turn_degrees) + ", the tube's mitred joint would explode");
    // The ring reaches r tan(turn / 2) back along each segment on the inner side of the bend; past half a
    // segment it could cross the neighbouring ring's reach and the wall between them would fold.
    const double reach = v.radii[i] * std::tan(turn / 2);
    const double room = 0.5 * std::min(v.length(a), v.length(i));
    if (reach > room)
      throw Error("the tube would fold at " + at_point(v.index, i, v.points[i]) + ": its radius " +
                  short_number(v.radii[i], 4) + " turning by " + deg + " degrees reaches " + short_number(reach, 4) +
                  " along its segments, more than half the shorter one (" + short_number(room, 4) + ")");
  }
}

// A unit vector across the path's first direction t: horizontal unless t is near vertical, so that a 2D
// curve's ring point 0 lies in the curve's plane.
Vec3 start_normal(Vec3 t) {
  const Vec3 up = std::abs(t.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
  return normalized(cross(up, t));
}

// u, across direction t, carried over a joint onto direction t2 by the smallest rotation taking t to t2.
// That rotation is two reflections (the double reflection method): in the plane normal to t, which leaves
// u as it is, then in the mitre plane, normal to t + t2, which takes -t to t2. Turns near 180 degrees, where
// t + t2 vanishes, are refused before.
Vec3 transported(Vec3 u, Vec3 t, Vec3 t2) {
  const Vec3 b = t + t2;
  const Vec3 v = u - (2 * dot(u, b) / dot(b, b)) * b;
  return normalized(v - dot(v, t2) * t2);  // rounding over millions of joints would pull u off the path
}

// The angle about the first direction by which the transported frame comes back after a closed path's loop.
double holonomy(const Path& v) {
  const Vec3 t0 = v.direction(0), u0 = start_normal(t0);
  Vec3 u = u0, t = t0;
  for (std::size_t j = 0; j < v.segments(); ++j) {
    const Vec3 t2 = v.direction(v.next(j));
    u = transported(u, t, t2);
    t = t2;
  }
  return std::atan2(dot(u, cross(t0, u0)), dot(u, u0));
}

// Which part of the tube triangle t belongs to, for the self-intersection message.
std::string part_text(std::span<const Path> paths, std::span<const std::size_t> triangle_begin, std::size_t sides,
                      std::size_t t) {
  const auto p = static_cast<std::size_t>(std::upper_bound(triangle_begin.begin(), triangle_begin.end(), t) -
                                          triangle_begin.begin() - 1);
  const Path& v = paths[p];
  const std::size_t local = t - triangle_begin[p], segment = local / (2 * sides);
  const std::string path = "path " + count(v.index);
  if (segment < v.segments())
    return path + " segment " + count(segment) + " (points " + count(segment) + " to " + count(segment + 1) + ")";
  return local - 2 * sides * v.segments() < sides ? path + "'s start cap (point 1)"
                                                  : path + "'s end cap (point " + std::to_string(v.rings()) + ")";
}

}  // namespace

void TubeOptions::validate() const { check_range(sides, 3, 256, "option 'sides'"); }

bool closed_path3(std::span<const Vec3> p) {
  if (p.size() < 3) return false;
  BBox3 box;
  for (Vec3 q : p) box.add(q);
  return norm(p.back() - p.front()) <= 1e-9 * std::max(1e-300, norm(box.size()));
}

double tube_size(const Polyline3& c, const TubeOptions& opt) {
  const Size s = curve_size(c, opt.sides);
  return s.points + s.triangles;
}

double tube_size(const Polyline& c, const TubeOptions& opt) {
  const Size s = curve_size(c, opt.sides);
  return s.points + s.triangles;
}

Mesh tube(const Polyline3& c, std::span<const double> radii, const TubeOptions& opt, Progress& progress) {
  opt.validate();
  check_curve(c, radii);
  const Size total = curve_size(c, opt.sides);
  check_budget(total.points + total.triangles, opt.budget, "the tube");
  if (total.points > max_mesh_points || total.triangles > max_mesh_points)
    throw Error("the tube would have " + number_text(total.triangles) + " triangles on " + number_text(total.points) +
                " points, more than 32-bit indices hold");
  std::vector<Path> paths;
  paths.reserve(c.paths());
  for (std::size_t i = 0; i < c.paths(); ++i) {
    paths.push_back(path_of(c, radii, i));
    check_path(paths.back());
  }

  const auto sides = static_cast<std::size_t>(opt.sides);
  std::vector<double> cosines(sides), sines(sides);
  for (std::size_t k = 0; k < sides; ++k) {
    const double a = 2 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(sides);
    cosines[k] = std::cos(a);
    sines[k] = std::sin(a);
  }
  const auto point_count = static_cast<std::size_t>(total.points);
  Mesh m;
  m.points.reserve(point_count);
  m.triangles.reserve(static_cast<std::size_t>(total.triangles));
  std::vector<std::uint32_t> source;  // the curve point each tube point stands for, for the fields
  source.reserve(point_count);
  std::vector<double> radius;
  radius.reserve(point_count);
  std::vector<std::int32_t> path_of_triangle;
  path_of_triangle.reserve(static_cast<std::size_t>(total.triangles));
  std::vector<std::size_t> triangle_begin;
  triangle_begin.reserve(paths.size());

  // Building is quick beside looking for self-intersections: a quarter of the reported progress.
  ProgressStage building(progress, 0, 0.25), checking(progress, 0.25, 1);
  std::size_t next_report = report_points;
  const auto add_point = [&](Vec3 p, std::size_t curve_point, double r) {
    m.points.push_back(p);
    source.push_back(static_cast<std::uint32_t>(curve_point));
    radius.push_back(r);
  };
  const auto add = [&](std::size_t a, std::size_t b, std::size_t c) {
    m.triangles.push_back(
        {static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b), static_cast<std::uint32_t>(c)});
  };

  for (const Path& v : paths) {
    const std::size_t base = m.points.size(), rings = v.rings();
    triangle_begin.push_back(m.triangles.size());
    // A closed path's frame comes back rotated by its holonomy h. Rings are polygons, so the seam may join
    // ring point k to point k + shift of the first ring: only h's remainder modulo one side's angle (at most
    // half a side) is left, and each ring turns back by an equal share of it, so no segment twists more than
    // another and none by more than pi / (sides * rings).
    const double side = 2 * std::numbers::pi / static_cast<double>(sides), h = v.closed ? holonomy(v) : 0;
    const double turns = std::round(h / side);
    const double twist = -(h - turns * side) / static_cast<double>(rings);
    const auto shift = static_cast<std::size_t>((static_cast<long long>(turns) % opt.sides + opt.sides) % opt.sides);
    Vec3 u = start_normal(v.direction(0));
    for (std::size_t i = 0; i < rings; ++i) {
      const std::size_t j = i < v.segments() ? i : i - 1;  // the segment whose frame places ring i
      const Vec3 t = v.direction(j);
      if (j > 0 && j == i) u = transported(u, v.direction(i - 1), t);
      // The ring lies in the mitre plane; taking the frame's circle there along t stretches it in the bend
      // direction by 1/cos(half the turn), so the walls stay straight and at the radius from the axis.
      const Vec3 normal = v.joint(i) ? normalized(v.direction(v.before(i)) + t) : t;
      const double g = twist * static_cast<double>(i), along = dot(t, normal);
      const Vec3 u1 = std::cos(g) * u + std::sin(g) * cross(t, u), w1 = cross(t, u1);
      const double r = v.radii[i];
      for (std::size_t k = 0; k < sides; ++k) {
        const Vec3 d = cosines[k] * u1 + sines[k] * w1;
        add_point(v.points[i] + r * (d - (dot(d, normal) / along) * t), v.first + i, r);
      }
      if (m.points.size() >= next_report) {
        building.step(static_cast<double>(m.points.size()) / total.points);
        next_report = m.points.size() + report_points;
      }
    }
    // Walls: ring points k, k + 1 on both rings, counter-clockwise about t, make the outward normal.
    for (std::size_t j = 0; j < v.segments(); ++j) {
      const std::size_t a = base + j * sides, b = base + v.next(j) * sides;
      const std::size_t turn = v.next(j) == 0 ? shift : 0;  // the seam (0 on an open path)
      for (std::size_t k = 0; k < sides; ++k) {
        const std::size_t k1 = k + 1 == sides ? 0 : k + 1, bk = b + (k + turn) % sides, bk1 = b + (k1 + turn) % sides;
        add(a + k, a + k1, bk1);
        add(a + k, bk1, bk);
      }
    }
    if (!v.closed) {
      // Flat caps: fans around centre points, facing back along the first segment and on along the last.
      const std::size_t start = base + rings * sides, end = start + 1, last = base + (rings - 1) * sides;
      add_point(v.points.front(), v.first, v.radii.front());
      add_point(v.points.back(), v.first + rings - 1, v.radii.back());
      for (std::size_t k = 0; k < sides; ++k) add(start, base + (k + 1) % sides, base + k);
      for (std::size_t k = 0; k < sides; ++k) add(end, last + k, last + (k + 1) % sides);
    }
    path_of_triangle.resize(m.triangles.size(), static_cast<std::int32_t>(v.index));
  }
  building.step(1);
  if (!m.finite()) throw Error("the tube has points that are not finite: its radii or coordinates are too large");

  if (const auto hit = first_intersection(m, checking))
    throw Error("the tube meets itself near " + place_text(hit->where) + ": " +
                part_text(paths, triangle_begin, sides, hit->first) + " and " +
                part_text(paths, triangle_begin, sides, hit->second) +
                " come closer than their two radii; a smaller radius, or a tube on a grid, where paths that meet "
                "merge into one solid: method = \"grid\"");

  m.point_fields = picked_fields<std::uint32_t>(c.point_fields, source, progress);
  m.point_fields.set(real_field("radius", std::move(radius)));
  if (!c.cell_fields.empty()) {
    const std::vector<std::uint32_t> cell(path_of_triangle.begin(), path_of_triangle.end());
    m.face_fields = picked_fields<std::uint32_t>(c.cell_fields, cell, progress);
  }
  m.face_fields.set(int_field("path", std::move(path_of_triangle)));
  return m;
}

Mesh tube(const Polyline& c, std::span<const double> radii, const TubeOptions& opt, Progress& progress) {
  // The budget first: the 3D copy below is the first allocation.
  opt.validate();
  check_budget(tube_size(c, opt), opt.budget, "the tube");
  Polyline3 c3;
  c3.points.resize(c.points.size());
  for (std::size_t i = 0; i < c.points.size(); ++i) c3.points[i] = {c.points[i].x, c.points[i].y, 0};
  c3.path_ends = c.path_ends;
  c3.point_fields = c.point_fields;
  c3.cell_fields = c.cell_fields;
  return tube(c3, radii, opt, progress);
}

}  // namespace selfsim::print
