#include "kernels/develop/develop.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "kernels/base/check.h"
#include "kernels/develop/level_stack.h"
#include "kernels/develop/tile_classes.h"
#include "kernels/geom/mesh_intersections.h"
#include "kernels/print/thicken.h"

namespace selfsim::develop {

namespace {

// The thickness field: level l's thickness is t·rate^l, or t·(segment length of level l / of level 0) for
// the self-similar thickness; between levels (route 2's `level` field is continuous) it goes geometrically.
void set_thickness(Mesh& m, std::span<const Polyline* const> levels, const DevelopOptions& opt) {
  std::vector<double> per_level;
  const double first = levels.front()->length() / static_cast<double>(levels.front()->segments());
  for (std::size_t l = 0; l < levels.size(); ++l)
    per_level.push_back(opt.thickness_rate > 0 ? opt.thickness * std::pow(opt.thickness_rate, static_cast<double>(l))
                                               : opt.thickness * (levels[l]->length() /
                                                                  static_cast<double>(levels[l]->segments()) / first));
  const Field* level = m.point_fields.find("level");
  std::vector<double> t(m.points.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double x = level->at(i);
    const auto l = std::min(static_cast<std::size_t>(x), per_level.size() - 1);
    const double frac = x - static_cast<double>(l);
    t[i] = frac > 0 ? per_level[l] * std::pow(per_level[l + 1] / per_level[l], frac) : per_level[l];
  }
  m.point_fields.set(real_field("thickness", std::move(t)));
}

// Where each tile of the control mesh c lies after `steps` rounds of Loop subdivision: its faces stay
// consecutive (children follow their parent) and its points a, f_s, e keep their indices.
TileLayout tile_layout(const Mesh& c, int steps) {
  const Field* tile = c.face_fields.find("tile");
  const auto tiles = static_cast<std::size_t>(tile->at(c.faces() - 1)) + 1;
  const std::size_t per = c.faces() / tiles, middle = (per - 1) / 2;
  TileLayout layout;
  layout.faces = per << (2 * steps);
  layout.stride = steps > 0 ? std::size_t{1} << (2 * (steps - 1)) : 1;
  for (std::size_t t = 0; t < tiles; ++t) layout.reference.push_back(c.triangles[t * per + middle]);
  return layout;
}

// m scaled about the origin so its largest side, or level size_level's, is opt.size (thicknesses too).
Mesh scaled(Mesh m, std::span<const Polyline* const> levels, const DevelopOptions& opt, double* scaled_by) {
  if (scaled_by) *scaled_by = 1;
  if (opt.size == 0) return m;
  double side = 0;
  if (opt.scale > 0) {
    side = opt.size / opt.scale;
  } else if (opt.size_level >= 0) {
    const Vec2 s = levels[static_cast<std::size_t>(opt.size_level)]->bbox().size();
    side = std::max(s.x, s.y);
  } else {
    const Vec3 s = m.bbox().size();
    side = std::max({s.x, s.y, s.z});
  }
  if (!(side > 0)) throw Error("the surface has no extent to scale to option 'size'");
  const double k = opt.scale > 0 ? opt.scale : opt.size / side;
  if (scaled_by) *scaled_by = k;
  for (Vec3& p : m.points) p = k * p;
  if (const Field* t = m.point_fields.find("thickness")) {
    std::vector<double> v(t->reals().begin(), t->reals().end());
    for (double& x : v) x *= k;
    m.point_fields.set(real_field("thickness", std::move(v)));
  }
  if (!m.finite()) throw Error("scaling to option 'size' overflows");
  return m;
}

}  // namespace

void DevelopOptions::validate() const {
  check_range(smooth, 0, 12, "option 'smooth'");
  if (resolution != 0) check_range(resolution, 1, 64, "option 'resolution'");
  // In the curve's units: its upper limit is relative to the surface's size (develop_surface).
  if (!(thickness >= 0 && std::isfinite(thickness)))
    throw Error("option 'thickness' must be a finite number, 0 or more, got " + number_text(thickness));
  if (thickness_rate != 0) check_between(thickness_rate, 1e-6, 1, "option 'thickness_rate'");
  if (size != 0) check_between(size, 1e-9, 1e9, "option 'size'");
  if (!(scale >= 0 && scale < 1e300))
    throw Error("option 'scale' must be a positive factor, got " + number_text(scale));
  // Options that would otherwise be ignored without a word.
  if (thickness_rate != 0 && thickness == 0) throw Error("option 'thickness_rate' needs a 'thickness' to shrink");
  if (size_level >= 0 && size == 0) throw Error("option 'size_level' needs a 'size' to scale that level to");
  if (bounded && smooth == 0) throw Error("option 'stencil' needs 'smooth' rounds of Loop subdivision to act in");
  if (method == Method::bezier) {
    // Route 2 smooths by its Bezier arcs: Loop's options have no meaning there.
    const char* loop_only = smooth > 0 ? "smooth" : corner_shift > 0 ? "corner_shift" : bounded ? "stencil" : nullptr;
    if (loop_only != nullptr)
      throw Error(std::string("option '") + loop_only +
                  "' is for method \"loop\" (Loop subdivision); method \"bezier\" is smooth by its Bezier arcs");
  } else if (resolution != 0) {
    throw Error("option 'resolution' is for method \"bezier\"; method \"loop\" refines with 'smooth'");
  }
}

double developed_size(std::span<const double> segments, bool closed, const DevelopOptions& opt) {
  const std::size_t top = segments.size() - 1;
  double v = 0, f = 0;
  for (std::size_t l = 0; l <= top; ++l) {
    v += segments[l] + (closed ? 0 : 1);
    if (l < top) f += segments[l] + segments[l + 1];
  }
  double e = v + f - (closed ? 0 : 1);
  double boundary = segments[0] + segments[top] + (closed ? 0 : 2 * static_cast<double>(top));
  for (int k = 0; k < opt.smooth; ++k) {
    v += e;
    e = 2 * e + 3 * f;
    f *= 4;
    boundary *= 2;
  }
  return opt.thickness > 0 ? 2 * v + 2 * f + 2 * boundary : v + f;
}

namespace {

// Route 2's surface, predicted (thickened: two sheets and a rim) before it is built.
Mesh bezier_route(std::span<const Polyline* const> levels, const DevelopOptions& opt, Progress& progress) {
  const BezierOptions bezier{opt.height, opt.resolution == 0 ? 4 : opt.resolution, opt.budget};
  const BezierCounts n = bezier_counts(levels, bezier);
  check_budget(opt.thickness > 0 ? 2 * (n.points + n.triangles + n.boundary_edges) : n.points + n.triangles, opt.budget,
               "method \"bezier\" at resolution = " + std::to_string(bezier.resolution));
  return bezier_surface(levels, bezier, progress);
}

// Route 1's surface with its tile classes, predicted before it is built.
Mesh loop_route(std::span<const Polyline* const> levels, const DevelopOptions& opt, Progress& progress) {
  {
    std::vector<double> segments;
    for (const Polyline* c : levels) segments.push_back(static_cast<double>(c->segments()));
    check_budget(developed_size(segments, closed_levels(levels), opt), opt.budget, "the surface");
  }
  ProgressStage build(progress, 0, opt.smooth > 0 ? 0.1 : 0.9);
  Mesh m = control_mesh(levels, {opt.height, opt.corner_shift}, build);
  const TileLayout layout = tile_layout(m, opt.smooth);
  if (opt.thickness > 0) set_thickness(m, levels, opt);
  if (opt.smooth > 0) {
    LoopOptions loop{opt.smooth, {}, opt.budget, opt.bounded};
    if (!closed_levels(levels)) {
      // Points are numbered level by level: level 0's two ends first, the finest level's ends last.
      const auto first_end = static_cast<std::uint32_t>(levels.front()->points.size() - 1);
      const auto last_start = static_cast<std::uint32_t>(m.points.size() - levels.back()->points.size());
      loop.corners = {0, first_end, last_start, static_cast<std::uint32_t>(m.points.size() - 1)};
    }
    ProgressStage smooth(progress, 0.1, 0.9);
    m = loop_subdivide(m, loop, smooth);
  }
  ProgressStage classes(progress, 0.9, 1);
  const std::vector<std::int32_t> of_tile = tile_classes(m, layout, classes);
  std::vector<std::int32_t> of_face(m.faces());
  for (std::size_t f = 0; f < of_face.size(); ++f) of_face[f] = of_tile[f / layout.faces];
  m.face_fields.set(int_field("tile_class", std::move(of_face)));
  return m;
}

// "triangle 12 (level 3, tile 7)": a face as a user can find it in ParaView (cell ids count from 0 there,
// as here).
std::string face_text(const Mesh& m, std::uint32_t f) {
  std::string s = "triangle " + std::to_string(f);
  std::string where;
  for (const char* name : {"level", "tile"})
    if (const Field* field = m.face_fields.find(name))
      where +=
          std::string(where.empty() ? "" : ", ") + name + " " + std::to_string(static_cast<long long>(field->at(f)));
  return where.empty() ? s : s + " (" + where + ")";
}

// The pair and where they meet, at `where` as the caller will see it (moved back from near the origin).
std::string pair_text(const Mesh& m, const TrianglePair& p, Vec3 where) {
  return face_text(m, p.first) + " meets " + face_text(m, p.second) + " at (" + number_text(where.x) + ", " +
         number_text(where.y) + ", " + number_text(where.z) + ")";
}

// A stack far from the origin for its size, moved to it: subdivision, tile classes and the checks then work
// with coordinates as small as the curve (at 1e5 from the origin, rounding alone would split a level-12
// dragon's tiles into thousands of classes), and develop_surface moves the result back. Near the origin the
// levels are used as they are.
struct NearOrigin {
  std::vector<Polyline> moved;
  std::vector<const Polyline*> levels;
  Vec2 offset{};
};

NearOrigin near_origin(std::span<const Polyline* const> levels) {
  BBox2 box;
  for (const Polyline* c : levels) box.add(c->bbox());
  NearOrigin n;
  const Vec2 centre = (box.min + box.max) * 0.5;
  if (norm(centre) > 4 * norm(box.size())) {
    n.offset = centre;
    for (const Polyline* c : levels) n.moved.push_back(transformed(*c, Similarity2{{1, 0}, Vec2{0, 0} - centre}));
    for (const Polyline& c : n.moved) n.levels.push_back(&c);
  } else {
    n.levels.assign(levels.begin(), levels.end());
  }
  return n;
}

}  // namespace

Mesh develop_surface(std::span<const Polyline* const> given, const DevelopOptions& opt, Progress& progress,
                     std::vector<std::string>* warnings, double* scaled_by) {
  opt.validate();
  progress.start("developing surface");
  check_stack(given);
  const NearOrigin near = near_origin(given);
  const std::span<const Polyline* const> levels = near.levels;
  if (opt.size_level >= static_cast<int>(levels.size()))
    throw Error("option 'size_level' must be a level of the stack, 0 to " + std::to_string(levels.size() - 1) +
                ", got " + std::to_string(opt.size_level));
  const double built = opt.thickness > 0 ? 0.6 : 0.9;
  ProgressStage surface(progress, 0, built);
  Mesh m = opt.method == Method::bezier ? bezier_route(levels, opt, surface) : loop_route(levels, opt, surface);
  const Vec3 back{near.offset.x, near.offset.y, 0};
  // Throws Error naming the first pair of the surface's triangles that meet.
  auto refuse_if_meeting = [&](const Mesh& surface, Progress& stage) {
    const auto p = first_intersection(surface, stage);
    if (!p) return;
    const std::string advice = opt.method == Method::bezier
                                   ? "the levels' smoothed curves, or the surface between them, cross"
                               : opt.smooth == 0 ? "shift its corners (corner_shift = 0.1) or smooth it"
                                                 : "shift its corners (corner_shift) or smooth it more";
    throw Error("the surface meets itself: " + pair_text(surface, *p, p->where + back) +
                (opt.size > 0 ? " (before scaling to option 'size')" : "") + "; " + advice +
                ", or keep it with check = false");
  };
  if (opt.thickness == 0) {
    if (opt.check) {
      ProgressStage check(progress, built, 1);
      refuse_if_meeting(m, check);
    }
    for (Vec3& p : m.points) p = p + back;
    return scaled(std::move(m), levels, opt, scaled_by);
  }
  if (opt.method == Method::bezier) set_thickness(m, levels, opt);
  const auto t = m.point_fields.find("thickness")->reals();
  const double thinnest = *std::min_element(t.begin(), t.end()), size = norm(m.bbox().size());
  // Thickness is in the curve's units, so its limit is relative: a stack 1e150 across needs a thick one.
  if (*std::max_element(t.begin(), t.end()) > 1e6 * size)
    throw Error("option 'thickness' gives sheets up to " + number_text(*std::max_element(t.begin(), t.end())) +
                " apart, more than 1e6 times the surface's size " + number_text(size));
  ProgressStage thick(progress, built, 0.8);
  Mesh solid = print::thicken(m, thick);
  for (Vec3& p : solid.points) p = p + back;
  solid = scaled(std::move(solid), levels, opt, scaled_by);
  if (opt.check) {
    // The solid's sheets lie along the surface: where the surface meets itself they do too, so the surface
    // is checked (and refused) only when the solid meets itself; otherwise that is the thickness's doing.
    ProgressStage check(progress, 0.8, 0.9);
    if (const auto p = first_intersection(solid, check)) {
      ProgressStage again(progress, 0.9, 1);
      refuse_if_meeting(m, again);
      if (warnings != nullptr)
        // A solid thinner somewhere than the check's tolerance (1e-9 of its size) touches itself there.
        warnings->push_back("the thickened solid meets itself (" + pair_text(solid, *p, p->where) + "): " +
                            (thinnest <= 1e-8 * size
                                 ? "its thickness falls to " + number_text(thinnest) +
                                       ", too thin to tell its sheets apart; raise thickness or thickness_rate"
                                 : "its thickness there is more than the gap between the surface's parts; "
                                   "lower thickness or thickness_rate"));
    }
  }
  return solid;
}

}  // namespace selfsim::develop
