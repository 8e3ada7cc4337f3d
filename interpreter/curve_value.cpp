#include "interpreter/curve_value.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "interpreter/lua_support.h"
#include "interpreter/options_reader.h"

namespace selfsim::interp {

namespace {

void push_point(lua_State* L, Vec2 p) {
  lua_createtable(L, 2, 0);
  lua_pushnumber(L, p.x);
  lua_rawseti(L, -2, 1);
  lua_pushnumber(L, p.y);
  lua_rawseti(L, -2, 2);
}

// {x, y} at index, both finite numbers.
Vec2 read_point(lua_State* L, int index, const std::string& what) {
  index = lua_absindex(L, index);
  if (lua_type(L, index) != LUA_TTABLE || lua_rawlen(L, index) != 2)
    throw Error(what + " must be {x, y}, got " + describe(L, index));
  lua_rawgeti(L, index, 1);
  lua_rawgeti(L, index, 2);
  const Vec2 p{finite_number(L, -2, what + " x"), finite_number(L, -1, what + " y")};
  lua_pop(L, 2);
  return p;
}

std::vector<Vec2> read_points(lua_State* L, int index, const std::string& what) {
  if (lua_type(L, index) != LUA_TTABLE)
    throw Error((what.empty() ? "argument" : what) + " must be a curve or a table of {x, y} points, got " +
                describe(L, index));
  std::vector<Vec2> pts;
  const lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, index));
  check_budget(static_cast<double>(n), run_budget(L), "a table of points");  // before copying it
  pts.reserve(static_cast<std::size_t>(n));
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_rawgeti(L, index, i);
    pts.push_back(read_point(L, -1, (what.empty() ? "" : what + " ") + "point " + std::to_string(i)));
    lua_pop(L, 1);
  }
  return pts;
}

int curve_points(lua_State* L) {
  const Held<Polyline> held = check_self<Polyline>(L, curve_type, "points");
  const Polyline& c = *held;
  lua_pushinteger(L, static_cast<lua_Integer>(c.points.size()));
  return 1;
}
int curve_segments(lua_State* L) {
  const Held<Polyline> held = check_self<Polyline>(L, curve_type, "segments");
  const Polyline& c = *held;
  lua_pushinteger(L, static_cast<lua_Integer>(c.segments()));
  return 1;
}
int curve_paths(lua_State* L) {
  const Held<Polyline> held = check_self<Polyline>(L, curve_type, "paths");
  const Polyline& c = *held;
  lua_pushinteger(L, static_cast<lua_Integer>(c.paths()));
  return 1;
}
int curve_length(lua_State* L) {
  const Held<Polyline> held = check_self<Polyline>(L, curve_type, "length");
  const Polyline& c = *held;
  lua_pushnumber(L, c.length());
  return 1;
}
int curve_level(lua_State* L) {
  const Held<Polyline> held = check_self<Polyline>(L, curve_type, "level");
  const Polyline& c = *held;
  lua_pushinteger(L, c.level);
  return 1;
}
// {min = {x, y}, max = {x, y}}
int curve_bbox(lua_State* L) {
  const Held<Polyline> held = check_self<Polyline>(L, curve_type, "bbox");
  const Polyline& c = *held;
  const BBox2 b = c.bbox();
  lua_createtable(L, 0, 2);
  push_point(L, b.min);
  lua_setfield(L, -2, "min");
  push_point(L, b.max);
  lua_setfield(L, -2, "max");
  return 1;
}
// c:point(i): the i-th point (1-based) as {x, y}, for checks in recipes; no bulk export to Lua.
int curve_point(lua_State* L) {
  const Held<Polyline> held = check_self<Polyline>(L, curve_type, "point");
  const Polyline& c = *held;
  const lua_Integer i = luaL_checkinteger(L, 2);
  if (i < 1 || i > static_cast<lua_Integer>(c.points.size()))
    return luaL_error(L, "point: index %I out of range [1, %I]", i, static_cast<lua_Integer>(c.points.size()));
  push_point(L, c.points[static_cast<std::size_t>(i - 1)]);
  return 1;
}
// c:transform{ mirror, scale, rotate, translate } -> a new curve: mirrored across the x axis, scaled
// about the origin, rotated by degrees counterclockwise, then translated, in that order.
int curve_transform(lua_State* L) {
  const Held<Polyline> held = check_self<Polyline>(L, curve_type, "transform");
  const Polyline& c = *held;
  return call_kernel(L, "transform", [&] {
    Options o(L, 2);
    const bool mirror = o.boolean("mirror", false);
    const double scale = o.number("scale", 1);
    const double degrees = o.number("rotate", 0);
    Vec2 shift{};
    if (o.push("translate") != LUA_TNIL) shift = read_point(L, -1, "option 'translate'");
    lua_pop(L, 1);
    o.finish();
    if (!(scale != 0)) throw Error("option 'scale' must be non-zero");
    const Similarity2 t{scale * polar(std::fmod(degrees, 360.0) * std::numbers::pi / 180), shift, mirror};
    check_budget(static_cast<double>(c.points.size()), run_budget(L), "transform");
    Polyline result = transformed(c, t);
    if (!result.finite()) throw Error("the result has non-finite coordinates (an overflow: scale the input down)");
    push_curve(L, std::move(result));
    return 1;
  });
}

int curve_tostring(lua_State* L) {
  const Held<Polyline> held = check_self<Polyline>(L, curve_type, "tostring");
  const Polyline& c = *held;
  lua_pushfstring(L, "Curve(%I points, %I paths, level %d)", static_cast<lua_Integer>(c.points.size()),
                  static_cast<lua_Integer>(c.paths()), c.level);
  return 1;
}

int make_polyline(lua_State* L, const char* fn, bool closed) {
  return call_kernel(L, fn, [&] {
    std::vector<Vec2> pts = read_points(L, 1, "");
    if (pts.size() < (closed ? 3u : 2u))
      throw Error(std::string("needs at least ") + (closed ? "3" : "2") + " points, got " + std::to_string(pts.size()));
    if (closed && !(pts.front() == pts.back())) pts.push_back(pts.front());
    check_budget(static_cast<double>(pts.size()), run_budget(L), fn);
    push_curve(L, Polyline::single(std::move(pts)));
    return 1;
  });
}

}  // namespace

void push_curve(lua_State* L, Polyline&& c) {
  const std::size_t bytes = c.points.capacity() * sizeof(Vec2) + c.path_ends.capacity() * sizeof(std::size_t);
  const double points = static_cast<double>(c.points.size());
  push_value(L, curve_type, std::move(c), points);
  // Lua only sees the userdata's few bytes; tell its collector about big arrays, so that curves a recipe
  // has dropped are freed before the next big one instead of piling up. (Small curves are left to the
  // collector's own pace: a step per tiny curve costs time in proportion to the whole heap.)
  if (bytes >= (std::size_t{1} << 20))
    lua_gc(L, LUA_GCSTEP, static_cast<int>(std::min<std::size_t>(bytes / 1024, 1 << 30)));
}

Held<Polyline> test_curve(lua_State* L, int index) { return test_value<Polyline>(L, index, curve_type); }

Polyline to_polyline(lua_State* L, int index, const std::string& what) {
  if (const Held<Polyline> c = test_curve(L, index)) return *c;
  return Polyline::single(read_points(L, lua_absindex(L, index), what));
}

void open_curve(lua_State* L) {
  static const luaL_Reg methods[] = {{"points", curve_points}, {"segments", curve_segments},   {"paths", curve_paths},
                                     {"length", curve_length}, {"level", curve_level},         {"bbox", curve_bbox},
                                     {"point", curve_point},   {"transform", curve_transform}, {nullptr, nullptr}};
  register_type<Polyline>(L, curve_type, methods, curve_tostring);
  lua_register(L, "polyline", [](lua_State* S) { return make_polyline(S, "polyline", false); });
  lua_register(L, "polygon", [](lua_State* S) { return make_polyline(S, "polygon", true); });
}

}  // namespace selfsim::interp
