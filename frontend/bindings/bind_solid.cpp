// solid.*: printable solids in millimetres (issue 25) — solid.thicken, solid.tube, solid.relief, solid.smooth,
// solid.size and solid.check. Thin adapters over kernels/print; the print check's reading of the options
// is shared with save() of a print format (print_options.h).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "frontend/bindings/bindings.h"
#include "frontend/bindings/print_options.h"
#include "frontend/lua/curve_value.h"
#include "frontend/lua/lua_support.h"
#include "frontend/lua/options_reader.h"
#include "frontend/lua/run_context.h"
#include "frontend/lua/value_types.h"
#include "kernels/base/check.h"
#include "kernels/develop/loop_subdivision.h"
#include "kernels/geom/mesh_intersections.h"
#include "kernels/geom/point_text.h"
#include "kernels/print/decimate.h"
#include "kernels/print/grid_thicken.h"
#include "kernels/print/grid_tube.h"
#include "kernels/print/print_size.h"
#include "kernels/print/relief.h"
#include "kernels/print/thicken.h"
#include "kernels/print/tube.h"

namespace selfsim::interp {

namespace {

// "takes a mesh and a table of options, solid.thicken(mesh, { ... })".
void check_arguments(lua_State* L, const std::string& call) {
  if (lua_gettop(L) > 2)
    throw Error("takes a value and a table of options, " + call + ", got " + std::to_string(lua_gettop(L)) +
                " arguments");
}

Held<Mesh> mesh_argument(lua_State* L, const std::string& call) {
  Held<Mesh> m = test_geometry<Mesh>(L, 1);
  if (!m) throw Error("argument 1 must be a mesh, " + call + ", got " + describe(L, 1));
  return m;
}

// A length option in millimetres: positive, finite, and at most 1e6 times the shape's size (a bigger one
// is a typo or a unit mix-up).
double length_option(Options& o, const char* key, double shape_size, const std::string& hint) {
  o.require(key, hint);
  const double v = o.number(key, 1);
  if (!(v > 0) || !std::isfinite(v))
    throw Error("option '" + std::string(key) + "' must be a positive length (mm), got " + number_text(v));
  if (shape_size > 0 && v > 1e6 * shape_size)
    throw Error("option '" + std::string(key) + "' is " + number_text(v) + ", more than 1e6 times the shape's size " +
                number_text(shape_size) + " (sizes are millimetres: scale the shape first, solid.size)");
  // Below a millionth of the shape, double precision cannot tell the solid's sides apart.
  if (shape_size > 0 && v < 1e-6 * shape_size)
    throw Error("option '" + std::string(key) + "' is " + number_text(v) + ", under a millionth of the shape's size " +
                number_text(shape_size) + " (sizes are millimetres)");
  return v;
}

template <class V>
double diagonal(const BBox<V>& b) {
  return norm(b.size());
}

// An exclusion surface carries its clearance (a uniform face field): pieces once apart keep it, so a
// thickness below it cannot fuse them, and one at or past it may.
void warn_past_clearance(lua_State* L, const Mesh& m, double thickness) {
  const Field* c = m.face_fields.find("clearance");
  if (c == nullptr || !c->uniform || c->scalar() != Scalar::Float64 || thickness < c->at(0)) return;
  const std::string message = recipe_where(L) + "solid.thicken: a thickness of " + mm_text(thickness) +
                              " reaches the surface's clearance of " + mm_text(c->at(0)) +
                              " (its last exclusion radius, which pieces once apart keep): they may fuse; below "
                              "it they cannot";
  lua_warning(L, message.c_str(), 0);
}

int solid_thicken(lua_State* L) {
  return call_kernel(L, "solid.thicken", [&] {
    const std::string call = "solid.thicken(mesh, { thickness = 1 })";
    check_arguments(L, call);
    const Held<Mesh> m = mesh_argument(L, call);
    Options o(L, 2);
    const double t = length_option(o, "thickness", diagonal(m->bbox()), "the solid's thickness in mm, e.g. 1");
    const bool grid = o.enumeration("method", {"sheets", "grid"}, 0) == 1;
    print::GridThickenOptions on_grid{.thickness = t};
    if (grid) {
      on_grid.voxel = o.number("voxel", 0);
      on_grid.adaptivity = o.number("adaptivity", 0);
    }
    const PrintCheckOption check = read_print_check(o);
    o.finish();
    warn_past_clearance(L, *m, t);
    Mesh solid;
    if (grid) {
      solid = with_budget(L, [&](const PointBudget& b) {
        on_grid.budget = b;
        return print::thicken_on_grid(*m, on_grid, RunContext::of(L));
      });
    } else {
      Mesh surface = *m;
      surface.point_fields.set(real_field("thickness", std::vector<double>(surface.points.size(), t)));
      // Two sheets and a rim: twice the points, twice the faces and two faces a boundary edge.
      check_run_budget(L, 2 * budget_size(*m) + 2 * 3 * static_cast<double>(m->faces()), "the thickened solid");
      solid = print::thicken(surface, RunContext::of(L));
    }
    push_geometry(L, std::move(solid));
    warn_unless_printable(L, "solid.thicken", test_geometry<Mesh>(L, -1), check);
    return 1;
  });
}

// The least radius a tube takes per point (mm): a nanometre, under anything a printer makes.
constexpr double min_tube_radius = 1e-6;

// The radius at each point of c: `radius`, times the point field `by` (taper absent), or times taper^by;
// none below `least` (0: no least). Throws Error for one below min_tube_radius (after `least`), naming how
// it came.
template <class C>
std::vector<double> tube_radii(const C& c, double radius, const std::string& by, double taper, double least) {
  std::vector<double> r(c.points.size(), std::max(radius, least));
  if (by.empty()) return r;
  const Field* f = c.point_fields.find(by);
  if (f == nullptr) throw Error("option 'by' names the point field '" + by + "', which the curve does not have");
  if (f->components != 1) throw Error("option 'by' must name a field of one component, '" + by + "' has more");
  for (std::size_t i = 0; i < r.size(); ++i) {
    const double v = f->at(f->uniform ? 0 : i);
    r[i] = std::max(taper > 0 ? radius * std::pow(taper, v) : radius * v, least);
    // Below a nanometre nothing prints, and a grid a quarter of it is past double precision's reach: say the
    // radius (radius * taper^by underflowed to 1e-300 and the voxel chosen from it was refused, naming neither).
    const bool tiny = r[i] >= 0 && r[i] < min_tube_radius && (taper > 0 || r[i] > 0);
    if (!tiny && (!(r[i] > 0) || !std::isfinite(r[i])))
      throw Error("the radius at point " + std::to_string(i + 1) + " is " + number_text(r[i]) + " (from field '" + by +
                  "' = " + number_text(v) + "): it must be positive");
    if (tiny) {
      std::string how = "radius * " + by + " = " + number_text(radius) + " * " + number_text(v);
      if (taper > 0) {
        // In logarithms: the power itself underflows to 0.
        const double e = std::log10(radius) + v * std::log10(taper), whole = std::floor(e);
        how = "radius * taper^" + by + " = " + number_text(radius) + " * " + number_text(taper) + "^" + number_text(v) +
              " = " + short_number(std::pow(10, e - whole), 2) + "e" + number_text(whole);
      }
      throw Error("the radius at point " + std::to_string(i + 1) + " is " + how +
                  " mm, under a nanometre (1e-6 mm): give a 'taper' nearer 1, a smaller '" + by +
                  "' or a 'min_radius'");
    }
  }
  return r;
}

// A grid tube with a radius per point (issue 40): its voxel (given, or a quarter of the thinnest radius within
// the budget) said unless quiet, and a warning when the thinnest parts are under a voxel across.
template <class C>
Mesh grid_tube_by(lua_State* L, const C& c, const std::vector<double>& radii, print::GridTubeOptions opt) {
  const bool given = opt.voxel > 0;
  double voxel = 0;
  Mesh solid = with_budget(L, [&](const PointBudget& b) {
    opt.budget = b;
    print::GridTubeOptions chosen = opt;
    chosen.voxel = voxel = print::grid_tube_voxel(c, radii, opt);
    return print::grid_tube(c, radii, chosen, RunContext::of(L));
  });
  const double thinnest = *std::min_element(radii.begin(), radii.end());
  if (!RunContext::of(L).config.quiet)
    std::printf("%ssolid.tube: radii %s to %s on a %s grid%s\n", recipe_where(L).c_str(), mm_text(thinnest).c_str(),
                mm_text(*std::max_element(radii.begin(), radii.end())).c_str(), mm_text(voxel).c_str(),
                given ? "" : " (a quarter of the thinnest radius, or coarser to fit the budget)");
  if (thinnest < voxel) {
    const std::string message = recipe_where(L) + "solid.tube: the thinnest radius " + mm_text(thinnest) +
                                " is under the voxel " + mm_text(voxel) +
                                ": parts that thin are lost or broken; give a smaller 'voxel' or a 'min_radius'";
    lua_warning(L, message.c_str(), 0);
  }
  return solid;
}

int solid_tube(lua_State* L) {
  return call_kernel(L, "solid.tube", [&] {
    const std::string call = "solid.tube(curve, { radius = 0.5 })";
    check_arguments(L, call);
    const Held<Polyline> c2 = test_geometry<Polyline>(L, 1);
    const Held<Polyline3> c3 = test_geometry<Polyline3>(L, 1);
    if (!c2 && !c3) throw Error("argument 1 must be a curve, " + call + ", got " + describe(L, 1));
    Options o(L, 2);
    const double size = c2 ? diagonal(c2->bbox()) : diagonal(c3->bbox());
    const double radius = length_option(o, "radius", size, "the tube's radius in mm, e.g. 0.5");
    const bool grid = o.enumeration("method", {"rings", "grid"}, 0) == 1;
    print::TubeOptions opt;
    print::GridTubeOptions on_grid{.radius = radius};
    if (grid) {
      if (o.has("sides"))
        throw Error("option 'sides' is for method = \"rings\"; a tube on the grid is round (its detail is 'voxel')");
      on_grid.voxel = o.number("voxel", 0);
      on_grid.adaptivity = o.number("adaptivity", 0);
    } else {
      opt.sides = static_cast<int>(o.integer("sides", opt.sides, 3, 256));
    }
    const std::string by = o.string("by", "");
    double taper = 0;
    if (o.has("taper")) {
      taper = check_between(o.number("taper", 1), 1e-6, 1e6, "option 'taper'");
      if (by.empty()) throw Error("option 'taper' needs 'by', the point field it is raised to (e.g. by = \"level\")");
    }
    const double least = o.has("min_radius") ? length_option(o, "min_radius", size, "") : 0;
    const PrintCheckOption check = read_print_check(o);
    o.finish();
    Mesh solid;
    if (grid && (!by.empty() || least > radius)) {
      solid = c2 ? grid_tube_by(L, *c2, tube_radii(*c2, radius, by, taper, least), on_grid)
                 : grid_tube_by(L, *c3, tube_radii(*c3, radius, by, taper, least), on_grid);
    } else {
      solid = with_budget(L, [&](const PointBudget& b) {
        opt.budget = on_grid.budget = b;
        if (grid)
          return c2 ? print::grid_tube(*c2, on_grid, RunContext::of(L))
                    : print::grid_tube(*c3, on_grid, RunContext::of(L));
        return c2 ? print::tube(*c2, tube_radii(*c2, radius, by, taper, least), opt, RunContext::of(L))
                  : print::tube(*c3, tube_radii(*c3, radius, by, taper, least), opt, RunContext::of(L));
      });
    }
    push_geometry(L, std::move(solid));
    warn_unless_printable(L, "solid.tube", test_geometry<Mesh>(L, -1), check);
    return 1;
  });
}

int solid_relief(lua_State* L) {
  return call_kernel(L, "solid.relief", [&] {
    const std::string call = "solid.relief(curve, { height = 2 })";
    check_arguments(L, call);
    const Held<Polyline> c = test_curve(L, 1);
    if (!c) throw Error("argument 1 must be a 2D curve (closed paths), " + call + ", got " + describe(L, 1));
    Options o(L, 2);
    print::ReliefOptions opt;
    opt.height = length_option(o, "height", diagonal(c->bbox()), "the relief's height in mm, e.g. 2");
    opt.base = o.number("base", 0);
    if (o.has("margin") && !(opt.base > 0))
      throw Error(
          "option 'margin' is the base plate's border beyond the outline: it needs 'base', the plate's "
          "thickness in mm (e.g. base = 1.5)");
    opt.margin = o.number("margin", opt.base > 0 ? 0.05 * std::max(c->bbox().size().x, c->bbox().size().y) : 0);
    const PrintCheckOption check = read_print_check(o);
    o.finish();
    Mesh solid = with_budget(L, [&](const PointBudget& b) {
      opt.budget = b;
      return print::relief(*c, opt, RunContext::of(L));
    });
    push_geometry(L, std::move(solid));
    warn_unless_printable(L, "solid.relief", test_geometry<Mesh>(L, -1), check);
    return 1;
  });
}

int solid_smooth(lua_State* L) {
  return call_kernel(L, "solid.smooth", [&] {
    const std::string call = "solid.smooth(mesh, { steps = 2 })";
    check_arguments(L, call);
    const Held<Mesh> m = mesh_argument(L, call);
    Options o(L, 2);
    develop::LoopOptions opt;
    opt.steps = static_cast<int>(o.integer("steps", 1, 0, 12));
    opt.bounded = o.enumeration("stencil", {"loop", "bounded"}, 0) == 1;
    const bool meets = o.boolean("meets", false);
    const PrintCheckOption check = read_print_check(o);
    o.finish();
    Mesh smooth = with_budget(L, [&](const PointBudget& b) {
      opt.budget = b;
      return develop::loop_subdivide(*m, opt, RunContext::of(L));
    });
    // Smoothing pulls a crumpled surface's folds towards each other: the same check develop makes.
    if (!meets)
      if (const auto p = first_intersection(smooth, RunContext::of(L)))
        throw Error("the smoothed mesh meets itself near " + point_text(p->where) + " (its triangles " +
                    std::to_string(p->first + 1) + " and " + std::to_string(p->second + 1) +
                    "): fewer steps, or keep it with meets = true");
    push_geometry(L, std::move(smooth));
    warn_unless_printable_solid(L, "solid.smooth", test_geometry<Mesh>(L, -1), check);
    return 1;
  });
}

int solid_decimate(lua_State* L) {
  return call_kernel(L, "solid.decimate", [&] {
    const std::string call = "solid.decimate(mesh, { triangles = 1000000 })";
    check_arguments(L, call);
    const Held<Mesh> m = mesh_argument(L, call);
    Options o(L, 2);
    o.require("triangles", "how many triangles to keep, e.g. triangles = 1000000");
    const double triangles = static_cast<double>(o.integer("triangles", 0, 4, 1LL << 40));
    const PrintCheckOption check = read_print_check(o);
    o.finish();
    check_run_budget(L, budget_size(*m), "the decimated copy");
    push_geometry(L, print::decimate(*m, triangles, RunContext::of(L)));
    warn_unless_printable_solid(L, "solid.decimate", test_geometry<Mesh>(L, -1), check);
    return 1;
  });
}

// solid.size(value, 80) or solid.size(value, { size = 80, axis = "x" } | { fit = {120, 120, 150} }).
int solid_size(lua_State* L) {
  return call_kernel(L, "solid.size", [&] {
    const std::string call = "solid.size(value, 80)";
    check_arguments(L, call);
    const std::optional<AnyValue> v = test_any(L, 1);
    if (!v) throw Error("argument 1 must be a mesh or a curve, " + call + ", got " + describe(L, 1));
    print::SizeOptions opt;
    if (lua_type(L, 2) == LUA_TNUMBER) {
      opt.size = finite_number(L, 2, "argument 2 (the largest side, mm)");
      if (!(opt.size > 0))
        throw Error("argument 2 (the largest side, mm) must be positive, got " + number_text(opt.size));
    } else {
      Options o(L, 2);
      opt.size = o.number("size", 0);
      opt.axis = o.enumeration("axis", {"x", "y", "z"}, -1);
      if (const auto fit = o.point3("fit")) {
        // Checked here: a box of zeros would read as no box at all.
        for (double side : {fit->x, fit->y, fit->z}) check_between(side, 1e-6, 1e6, "each side of option 'fit' (mm)");
        opt.fit = *fit;
      }
      o.finish();
    }
    const io::ValueRef ref = v->ref();
    BBox3 box;
    if (const auto* m = std::get_if<const Mesh*>(&ref)) box = (*m)->bbox();
    if (const auto* c = std::get_if<const Polyline3*>(&ref)) box = (*c)->bbox();
    if (const auto* c = std::get_if<const Polyline*>(&ref)) {
      const BBox<Vec2> b = (*c)->bbox();
      box = {{b.min.x, b.min.y, 0}, {b.max.x, b.max.y, 0}};
      if (opt.axis == 2) throw Error("option 'axis' is \"z\", but a 2D curve has no depth");
    }
    const double k = print::size_factor(box, opt);
    check_run_budget(L, static_cast<double>(v->points()), "the scaled copy");
    Vec3 size = k * box.size();
    if (const auto* m = std::get_if<const Mesh*>(&ref)) push_geometry(L, print::scaled_by(**m, k));
    if (const auto* c = std::get_if<const Polyline3*>(&ref)) push_geometry(L, print::scaled_by(**c, k));
    if (const auto* c = std::get_if<const Polyline*>(&ref)) push_geometry(L, print::scaled_by(**c, k));
    if (!RunContext::of(L).config.quiet)
      std::printf("%ssolid.size: %s\n", recipe_where(L).c_str(), print::size_text(size).c_str());
    return 1;
  });
}

// solid.check(mesh, { profile, nozzle, min_wall, min_gap, triangles, bed, voxel }) -> report, marked mesh.
int solid_check(lua_State* L) {
  return call_kernel(L, "solid.check", [&] {
    const std::string call = "solid.check(mesh, { profile = \"fdm\" })";
    check_arguments(L, call);
    const Held<Mesh> m = mesh_argument(L, call);
    Options o(L, 2);
    const print::PrintRules rules = read_print_rules(o);
    o.finish();
    check_run_budget(L, budget_size(*m), "the checked copy with fields wall and gap");
    Mesh marked;
    const print::PrintReport r = check_print_in_run(L, m, rules, &marked);
    push_print_report(L, r);
    push_geometry(L, std::move(marked));
    keep_print_report(L, test_geometry<Mesh>(L, -1), r);  // the same solid: saving it checks nothing again
    return 2;
  });
}

}  // namespace

void open_solid(lua_State* L) {
  const luaL_Reg functions[] = {{"thicken", solid_thicken},   {"tube", solid_tube}, {"relief", solid_relief},
                                {"smooth", solid_smooth},     {"size", solid_size}, {"check", solid_check},
                                {"decimate", solid_decimate}, {nullptr, nullptr}};
  luaL_newlib(L, functions);
  add_solid_placing(L);
  add_solid_union(L);
  lua_setglobal(L, "solid");
}

}  // namespace selfsim::interp
