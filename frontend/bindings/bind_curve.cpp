// The Curve and Curve3 types' own methods (segments, paths, length, level, transform, reverse, rounded) and
// the polyline{} / polygon{} constructors; the value itself as the interpreter holds it is curve_value.h.
#include <cmath>
#include <numbers>

#include "frontend/bindings/bindings.h"
#include "frontend/lua/curve_value.h"
#include "frontend/lua/growth.h"
#include "frontend/lua/lua_support.h"
#include "frontend/lua/options_reader.h"
#include "frontend/lua/point_reader.h"
#include "kernels/geom/similarity3.h"

namespace selfsim::interp {

namespace {

template <class T>
int curve_segments(lua_State* L) {
  const Held<T> c = geometry_self<T>(L, "segments");
  lua_pushinteger(L, static_cast<lua_Integer>(c->segments()));
  return 1;
}
template <class T>
int curve_paths(lua_State* L) {
  const Held<T> c = geometry_self<T>(L, "paths");
  lua_pushinteger(L, static_cast<lua_Integer>(c->paths()));
  return 1;
}
template <class T>
int curve_length(lua_State* L) {
  const Held<T> c = geometry_self<T>(L, "length");
  return call_kernel(L, "length", [&] {
    const double length = c->length();
    if (!std::isfinite(length)) throw Error("the curve's length overflows (its coordinates are too far apart)");
    lua_pushnumber(L, length);
    return 1;
  });
}
// c:level(): the construction level a kernel recorded (its uniform `level` field), or nil; c:level(k): the
// curve at level k (growth.h).
template <class T>
int curve_level(lua_State* L) {
  if (lua_gettop(L) >= 2) return value_level(L);
  const Held<T> c = geometry_self<T>(L, "level");
  const Field* level = c->point_fields.find("level");
  if (level != nullptr && level->uniform)
    lua_pushinteger(L, static_cast<lua_Integer>(level->at(0)));
  else
    lua_pushnil(L);
  return 1;
}
// c:transform{ mirror, scale, rotate, translate } -> a new curve: mirrored across the x axis, scaled
// about the origin, rotated by degrees counterclockwise, then translated, in that order.
int curve_transform(lua_State* L) {
  const Held<Polyline> held = geometry_self<Polyline>(L, "transform");
  const Polyline& c = *held;
  return call_kernel(L, "transform", [&] {
    Options o(L, 2);
    const bool mirror = o.boolean("mirror", false);
    const double scale = o.number("scale", 1);
    const double degrees = o.number("rotate", 0);
    const Vec2 shift = o.point2("translate").value_or(Vec2{});
    o.finish();
    if (!(scale != 0)) throw Error("option 'scale' must be non-zero");
    const Similarity2 t{scale * polar(std::fmod(degrees, 360.0) * std::numbers::pi / 180), shift, mirror};
    check_run_budget(L, static_cast<double>(c.points.size()), "transform");
    Polyline result = transformed(c, t);
    if (!result.finite()) throw Error("the result has non-finite coordinates (an overflow: scale the input down)");
    push_curve(L, std::move(result));
    return 1;
  });
}

// c:transform{ mirror, scale, rotate, axis, translate } on a 3D curve: mirrored across the xz-plane (y
// negated), scaled about the origin, rotated by degrees about `axis` (default {0, 0, 1}: as a 2D curve
// turns), then translated.
int curve3_transform(lua_State* L) {
  const Held<Polyline3> held = geometry_self<Polyline3>(L, "transform");
  const Polyline3& c = *held;
  return call_kernel(L, "transform", [&] {
    Options o(L, 2);
    const bool mirror = o.boolean("mirror", false);
    const double scale = o.number("scale", 1);
    const double degrees = o.number("rotate", 0);
    const Vec3 axis = o.point3("axis").value_or(Vec3{0, 0, 1});
    const Vec3 shift = o.point3("translate").value_or(Vec3{});
    o.finish();
    if (!(scale != 0)) throw Error("option 'scale' must be non-zero");
    if (!(norm(axis) > 0)) throw Error("option 'axis' must be a non-zero vector");
    Similarity3 t =
        Similarity3::rotation(axis / norm(axis), std::fmod(degrees, 360.0)).after(Similarity3::scaling(scale));
    if (mirror) t = t.after(Similarity3{{Vec3{1, 0, 0}, Vec3{0, -1, 0}, Vec3{0, 0, 1}}, {}});
    t.t = shift;
    check_run_budget(L, static_cast<double>(c.points.size()), "transform");
    Polyline3 result = transformed(c, t);
    if (!result.finite()) throw Error("the result has non-finite coordinates (an overflow: scale the input down)");
    push_geometry(L, std::move(result));
    return 1;
  });
}

// polyline{ {x, y}, ... } or polygon{...}: a Curve; with {x, y, z} points, a Curve3.
template <class V>
void push_polyline(lua_State* L, const char* fn, bool closed) {
  std::vector<V> pts = read_point_list<V>(L, 1, "");
  if (pts.size() < (closed ? 3u : 2u))
    throw Error(std::string("needs at least ") + (closed ? "3" : "2") + " points, got " + std::to_string(pts.size()));
  if (closed && !(pts.front() == pts.back())) pts.push_back(pts.front());
  check_run_budget(L, static_cast<double>(pts.size()), fn);
  push_geometry(L, PolylineT<V>::single(std::move(pts)));
}

int make_polyline(lua_State* L, const char* fn, bool closed) {
  return call_kernel(L, fn, [&] {
    // The first point's size decides: {x, y} or {x, y, z}.
    const bool three = lua_type(L, 1) == LUA_TTABLE && lua_rawgeti(L, 1, 1) == LUA_TTABLE && lua_rawlen(L, -1) == 3;
    if (three)
      push_polyline<Vec3>(L, fn, closed);
    else
      push_polyline<Vec2>(L, fn, closed);
    return 1;
  });
}

}  // namespace

void open_curve(lua_State* L) {
  const char* const level_takes = "one level number: c:level(3) (or none: the level it was made at)";
  const char* const transform_takes = "one table: c:transform{ mirror, scale, rotate, translate }";
  register_geometry<Polyline>(L, {{"segments", curve_segments<Polyline>, 0, "no arguments: c:segments()"},
                                  {"paths", curve_paths<Polyline>, 0, "no arguments: c:paths()"},
                                  {"length", curve_length<Polyline>, 0, "no arguments: c:length()"},
                                  {"level", curve_level<Polyline>, 1, level_takes},
                                  {"transform", curve_transform, 1, transform_takes},
                                  {"reverse", curve_reverse<Vec2>, 0, "no arguments: c:reverse()"},
                                  {"rounded", curve_rounded, 1, "a table of options, c:rounded{ samples = 8 }"}});
  register_geometry<Polyline3>(L, {{"segments", curve_segments<Polyline3>, 0, "no arguments: c:segments()"},
                                   {"paths", curve_paths<Polyline3>, 0, "no arguments: c:paths()"},
                                   {"length", curve_length<Polyline3>, 0, "no arguments: c:length()"},
                                   {"level", curve_level<Polyline3>, 1, level_takes},
                                   {"transform", curve3_transform, 1, transform_takes},
                                   {"reverse", curve_reverse<Vec3>, 0, "no arguments: c:reverse()"}});
  lua_register(L, "polyline", [](lua_State* S) { return make_polyline(S, "polyline", false); });
  lua_register(L, "polygon", [](lua_State* S) { return make_polyline(S, "polygon", true); });
}

}  // namespace selfsim::interp
