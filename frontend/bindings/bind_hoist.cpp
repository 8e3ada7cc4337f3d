// Seed 000's smooth self-similar curves: bspline{}, catmull_rom{}, hoist.onto / multiply / iterate /
// mirror / rotate, and simplify(). A thin adapter over kernels/hoist.
#include <cmath>

#include "frontend/bindings/bindings.h"
#include "frontend/lua/curve_value.h"
#include "frontend/lua/growth.h"
#include "frontend/lua/lua_support.h"
#include "frontend/lua/options_reader.h"
#include "frontend/lua/point_reader.h"
#include "frontend/lua/run_context.h"
#include "kernels/base/check.h"
#include "kernels/hoist/hoist.h"
#include "kernels/hoist/iterate.h"
#include "kernels/hoist/multiply.h"
#include "kernels/hoist/simplify.h"
#include "kernels/hoist/spline.h"
#include "kernels/hoist/symmetric_controls.h"

namespace selfsim::interp {

namespace {

using hoist::Boundary;

const std::vector<std::string> boundary_names{"clamp", "repeat", "reflect_y", "reflect_x", "rotate"};
// Segment modes (seed 000 §3.2): every copy as is, or every other copy transformed.
const std::vector<std::string> segment_modes{"repeat", "reflect_y", "reflect_x", "rotate"};
// One copy's transform, named by the axes of the unit frame (kernels/geom/segment_transform.h).
const std::vector<std::string> copy_names{"identity", "reflect_x", "reflect_y", "rotate"};
const SegmentTransform copy_transforms[] = {SegmentTransform::Identity, SegmentTransform::ReflectSegment,
                                            SegmentTransform::ReflectBisector, SegmentTransform::HalfTurn};

Boundary read_boundary(Options& o) { return static_cast<Boundary>(o.enumeration("boundary", boundary_names, 0)); }

// `segments`: a mode name, or one transform per copy (⌈multiplicity⌉ of them).
std::vector<SegmentTransform> read_segments(lua_State* L, Options& o, double multiplicity) {
  const int type = o.push("segments");
  std::vector<SegmentTransform> out;
  if (type == LUA_TSTRING) {
    const std::string name = text_value(L, -1, "option 'segments'");
    switch (enum_index(name, segment_modes, "segments mode")) {
      case 1:
        out = {SegmentTransform::Identity, SegmentTransform::ReflectBisector};
        break;
      case 2:
        out = {SegmentTransform::Identity, SegmentTransform::ReflectSegment};
        break;
      case 3:
        out = {SegmentTransform::Identity, SegmentTransform::HalfTurn};
        break;
      default:
        break;
    }
  } else if (type == LUA_TTABLE) {
    const lua_Integer n = list_length(L, -1, "option 'segments'");
    const double copies = hoist::copies(multiplicity);
    if (static_cast<double>(n) != copies)
      throw Error("option 'segments' lists " + std::to_string(n) + " transforms for " + number_text(copies) +
                  " copies (one per copy at multiplicity " + number_text(multiplicity) +
                  "), or name a mode: 'repeat', 'reflect_y', 'reflect_x', 'rotate'");
    for (lua_Integer i = 1; i <= n; ++i) {
      lua_rawgeti(L, -1, i);
      const std::string what = "option 'segments' entry " + std::to_string(i);
      if (lua_type(L, -1) != LUA_TSTRING) throw Error(what + " must be a transform name, got " + describe(L, -1));
      out.push_back(copy_transforms[enum_index(text_value(L, -1, what), copy_names, "copy transform",
                                               " (entry " + std::to_string(i) + ")")]);
      lua_pop(L, 1);
    }
  } else if (type != LUA_TNIL) {
    throw Error("option 'segments' must be a mode name or a list of transforms, got " + describe(L, -1));
  }
  lua_pop(L, 1);
  return out;
}

int make_spline(lua_State* L, const char* fn, hoist::SplineKind kind) {
  return call_kernel(L, fn, [&] {
    Options o(L, 1);
    o.require("points", "the control points, from {0, 0} to {1, 0}");
    hoist::SplineOptions opt;
    opt.kind = kind;
    opt.points = o.points2("points");
    opt.flatness = o.number("flatness", opt.flatness);
    opt.normalize = o.boolean("normalize", false);
    o.finish();
    push_curve(L, with_budget(L, [&](const PointBudget& b) {
                 opt.budget = b;
                 return hoist::sample_spline(opt, RunContext::of(L));
               }));
    return 1;
  });
}

int hoist_onto(lua_State* L) {
  return call_kernel(L, "hoist.onto", [&] {
    const Held<Polyline> q = held_curve(L, 1, "argument 1 (the path Q)");
    const Held<Polyline> p = held_curve(L, 2, "argument 2 (the base curve P)");
    Options o(L, 3);
    const Boundary boundary = read_boundary(o);
    o.finish();
    const hoist::BaseCurve base(*p);
    check_run_budget(L, static_cast<double>(q->points.size()), "hoist.onto");
    push_curve(L, hoist::hoist_onto(*q, base, boundary, RunContext::of(L)));
    return 1;
  });
}

int hoist_multiply(lua_State* L) {
  return call_kernel(L, "hoist.multiply", [&] {
    const Held<Polyline> c = held_curve(L, 1, "argument 1 (the curve)");
    hoist::MultiplyOptions opt;
    opt.multiplicity = finite_number(L, 2, "argument 2 (the multiplicity)");
    opt.validate();
    Options o(L, 3);
    opt.transforms = read_segments(L, o, opt.multiplicity);
    o.finish();
    push_curve(L, with_budget(L, [&](const PointBudget& b) {
                 opt.budget = b;
                 return hoist::multiply(*c, opt, RunContext::of(L));
               }));
    return 1;
  });
}

int hoist_iterate(lua_State* L) {
  return call_kernel(L, "hoist.iterate", [&] {
    const Held<Polyline> p = held_curve(L, 1, "argument 1 (the base curve P)");
    Options o(L, 2);
    o.require("multiplicity", "copies of the curve per generation, e.g. multiplicity = 3");
    o.require("generations", "rounds of multiplying and hoisting, e.g. generations = 4");
    hoist::IterateOptions opt;
    opt.multiplicity = o.number("multiplicity", opt.multiplicity);
    opt.generations = static_cast<int>(o.integer("generations", opt.generations, 0, 64));
    opt.boundary = read_boundary(o);
    // A list of per-copy transforms is counted against the multiplicity, so that is checked first; a
    // missing multiplicity is named by finish().
    if (o.has("multiplicity")) {
      opt.validate();
      opt.transforms = read_segments(L, o, opt.multiplicity);
    } else {
      o.push("segments");  // marked read: finish() names the missing multiplicity instead
      lua_pop(L, 1);
    }
    o.finish();
    opt.validate();
    push_curve(L, with_budget(L, [&](const PointBudget& b) {
                 opt.budget = b;
                 return hoist::iterate(*p, opt, RunContext::of(L));
               }));
    // Its generations: the same iteration stopped earlier.
    attach_growth(L, Growth{0, opt.generations, "generation", budget_size(*p),
                            [p, opt](int k, const PointBudget& b, Progress& pr) {
                              hoist::IterateOptions at = opt;
                              at.generations = k;
                              at.budget = b;
                              return GrownValue(hoist::iterate(*p, at, pr));
                            }});
    return 1;
  });
}

int push_points(lua_State* L, const std::vector<Vec2>& pts) {
  lua_createtable(L, static_cast<int>(pts.size()), 0);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    push_point(L, pts[i]);
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  return 1;
}

int hoist_mirror(lua_State* L) {
  return call_kernel(L, "hoist.mirror", [&] {
    return push_points(L, hoist::mirror_controls(read_point_list<Vec2>(L, 1, "argument 1 (the first half)")));
  });
}

int hoist_rotate(lua_State* L) {
  return call_kernel(L, "hoist.rotate", [&] {
    return push_points(L, hoist::rotate_controls(read_point_list<Vec2>(L, 1, "argument 1 (the first half)")));
  });
}

int make_simplify(lua_State* L) {
  return call_kernel(L, "simplify", [&] {
    const Held<Polyline> c = held_curve(L, 1, "argument 1 (the curve)");
    const double tolerance = finite_number(L, 2, "argument 2 (the tolerance)");
    check_run_budget(L, static_cast<double>(c->points.size()), "simplify");
    push_curve(L, hoist::simplify(*c, tolerance, RunContext::of(L)));
    return 1;
  });
}

}  // namespace

void open_hoist(lua_State* L) {
  lua_register(L, "bspline", [](lua_State* S) { return make_spline(S, "bspline", hoist::SplineKind::BSpline); });
  lua_register(L, "catmull_rom",
               [](lua_State* S) { return make_spline(S, "catmull_rom", hoist::SplineKind::CatmullRom); });
  lua_register(L, "simplify", make_simplify);
  const luaL_Reg functions[] = {{"onto", hoist_onto},     {"multiply", hoist_multiply}, {"iterate", hoist_iterate},
                                {"mirror", hoist_mirror}, {"rotate", hoist_rotate},     {nullptr, nullptr}};
  luaL_newlib(L, functions);
  lua_setglobal(L, "hoist");
}

}  // namespace selfsim::interp
