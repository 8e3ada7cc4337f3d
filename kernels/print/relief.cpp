#include "kernels/print/relief.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "kernels/base/check.h"
#include "kernels/base/error.h"
#include "kernels/region/region_triangles.h"

namespace selfsim::print {

namespace {

using Index = std::uint32_t;

// Throws unless value lies within 1e-9 to 1e6 times the region's size: a relief a million times taller than
// wide, or a billionth as tall, is a slip of units, not a print.
void check_scale(double value, double size, const char* option) {
  if (value > 1e6 * size || value < 1e-9 * size)
    throw Error(std::string("option '") + option + "' of " + number_text(value) +
                " is absurd beside the region's size of " + number_text(size) +
                " (it must lie within 1e-9 to 1e6 times it)");
}

// The mesh under construction: points with their heights, triangles with their parts.
struct Builder {
  Mesh mesh;
  std::vector<double> heights;
  std::vector<std::int32_t> parts;

  void point(Vec2 p, double z) {
    mesh.points.push_back({p.x, p.y, z});
    heights.push_back(z);
  }
  void triangle(Index a, Index b, Index c, std::int32_t part) {
    mesh.triangles.push_back({a, b, c});
    parts.push_back(part);
  }
  // Two triangles facing out of the region, over the boundary edge from foot point a to foot point b (the
  // region on its left), whose tops are a_top and b_top.
  void wall(Index a, Index b, Index a_top, Index b_top, std::int32_t part) {
    triangle(a, b, b_top, part);
    triangle(a, b_top, a_top, part);
  }
};

}  // namespace

void ReliefOptions::validate() const {
  if (!(height > 0 && std::isfinite(height)))
    throw Error("option 'height' must be a positive finite number, got " + number_text(height));
  if (!(base >= 0 && std::isfinite(base)))
    throw Error("option 'base' must be a finite thickness >= 0 (0: no plate), got " + number_text(base));
  if (!(margin >= 0 && std::isfinite(margin)))
    throw Error("option 'margin' must be a finite distance >= 0, got " + number_text(margin));
  if (base > 0 && margin == 0)
    throw Error("option 'margin' must be positive under a base plate (the outlines would touch the plate's edge)");
}

double relief_size(const Polyline& c, const ReliefOptions& opt) {
  const double paths = static_cast<double>(c.paths());
  const double n = std::max(0.0, static_cast<double>(c.points.size()) - paths);  // without closing repeats
  // A cap of an outline with h holes has n + 2h - 2 triangles; the walls two per boundary edge.
  if (opt.base > 0) return (2 * n + 8) + (n + 2 * paths) + (n + 4 + 2 * (paths + 1)) + 2 * n + 10;
  return 2 * n + 2 * (n + 2 * paths) + 2 * n;
}

Mesh relief(const Polyline& c, const ReliefOptions& opt, Progress& progress) {
  opt.validate();
  check_budget(relief_size(c, opt), opt.budget, "the relief");
  const Vec2 extent = c.bbox().size();
  const double size = std::max(extent.x, extent.y);
  if (size > 0 && std::isfinite(size)) {  // else the region's own checks name the fault
    check_scale(opt.height, size, "height");
    if (opt.base > 0) {
      check_scale(opt.base, size, "base");
      check_scale(opt.margin, size, "margin");
    }
  }
  const bool plate = opt.base > 0;
  ProgressStage region_stage(progress, 0, plate ? 0.45 : 0.9);
  const RegionTriangles region = region_triangles(c, region_stage, "a relief");
  const auto n = static_cast<Index>(region.points.size());

  Builder b;
  b.mesh.points.reserve(2 * static_cast<std::size_t>(n) + 8);
  for (Vec2 p : region.points) b.point(p, opt.height);  // [0, n): the top
  for (Vec2 p : region.points) b.point(p, 0);           // [n, 2n): the foot
  for (const auto& t : region.triangles) b.triangle(t[0], t[1], t[2], 1);
  for (Index v = 0; v < n; ++v) b.wall(n + v, n + region.next[v], v, region.next[v], 2);

  if (!plate) {
    for (const auto& t : region.triangles) b.triangle(n + t[0], n + t[2], n + t[1], 0);
  } else {
    // The plate's top: its rectangle with the region's paths, one level deeper each (outlines become holes).
    BBox2 box = bbox_of<Vec2>(region.points);
    box.min = box.min - Vec2::all(opt.margin);
    box.max = box.max + Vec2::all(opt.margin);
    Polyline with_plate;
    with_plate.points.assign({box.min, {box.max.x, box.min.y}, box.max, {box.min.x, box.max.y}, box.min});
    with_plate.close_path();
    with_plate.points.insert(with_plate.points.end(), c.points.begin(), c.points.end());
    for (std::size_t end : c.path_ends) with_plate.path_ends.push_back(5 + end);
    ProgressStage plate_stage(progress, 0.45, 0.9);
    const RegionTriangles top = region_triangles(with_plate, plate_stage, "a relief's base plate");
    // Its vertices after the rectangle's four are the region's, in the same order.
    bool same = top.points.size() == 4 + static_cast<std::size_t>(n);
    for (Index v = 0; same && v < n; ++v) same = top.source[4 + v] == region.source[v] + 5;
    if (!same) throw Error("a relief's base plate lost track of the region's points (please report this curve)");
    const Index corners = 2 * n, feet = 2 * n + 4;
    for (Index q = 0; q < 4; ++q) b.point(top.points[q], 0);          // [2n, 2n+4): the plate's top corners
    for (Index q = 0; q < 4; ++q) b.point(top.points[q], -opt.base);  // [2n+4, 2n+8): its bottom corners
    auto at = [&](Index q) { return q < 4 ? corners + q : n + (q - 4); };
    for (const auto& t : top.triangles) b.triangle(at(t[0]), at(t[1]), at(t[2]), 0);
    Index q[4] = {0, top.next[0], top.next[top.next[0]], top.next[top.next[top.next[0]]]};  // counter-clockwise
    b.triangle(feet + q[0], feet + q[2], feet + q[1], 0);
    b.triangle(feet + q[0], feet + q[3], feet + q[2], 0);
    for (Index k = 0; k < 4; ++k)
      b.wall(feet + q[k], feet + q[(k + 1) % 4], corners + q[k], corners + q[(k + 1) % 4], 0);
  }
  progress.step(0.95);
  b.mesh.point_fields.set(real_field("height", std::move(b.heights)));
  b.mesh.face_fields.set(int_field("part", std::move(b.parts)));
  progress.fraction(1);
  return std::move(b.mesh);
}

}  // namespace selfsim::print
