#include "frontend/lua/value_types.h"

#include <algorithm>
#include <string>

#include "frontend/lua/growth.h"
#include "frontend/lua/options_reader.h"

namespace selfsim::interp {

namespace {

void push_coordinates(lua_State* L, std::initializer_list<double> xs) {
  lua_createtable(L, static_cast<int>(xs.size()), 0);
  lua_Integer i = 0;
  for (double x : xs) {
    lua_pushnumber(L, x);
    lua_rawseti(L, -2, ++i);
  }
}

}  // namespace

void push_point(lua_State* L, Vec2 p) { push_coordinates(L, {p.x, p.y}); }
void push_point(lua_State* L, Vec3 p) { push_coordinates(L, {p.x, p.y, p.z}); }

template <class V>
void push_bbox(lua_State* L, const BBox<V>& b) {
  lua_createtable(L, 0, 2);
  push_point(L, b.min);
  lua_setfield(L, -2, "min");
  push_point(L, b.max);
  lua_setfield(L, -2, "max");
}
template void push_bbox(lua_State*, const BBox2&);
template void push_bbox(lua_State*, const BBox3&);

namespace {

// ", level 8" (or ", generation 4") where a kernel recorded one for the whole curve.
std::string recorded(const Fields& f, const char* name) {
  const Field* field = f.find(name);
  if (field == nullptr || !field->uniform) return "";
  return std::string(", ") + name + " " + std::to_string(static_cast<long long>(field->at(0)));
}

std::string summary(const Polyline& c) {
  return "Curve(" + std::to_string(c.points.size()) + " points, " + std::to_string(c.paths()) + " paths" +
         recorded(c.point_fields, "level") + recorded(c.point_fields, "generation") + ")";
}
std::string summary(const Polyline3& c) {
  return "Curve3(" + std::to_string(c.points.size()) + " points, " + std::to_string(c.paths()) + " paths)";
}
std::string summary(const Mesh& m) {
  return "Mesh(" + std::to_string(m.points.size()) + " points, " + std::to_string(m.faces()) + " faces)";
}

// v:point(i): the i-th point (1-based) as {x, y} or {x, y, z}, for checks in recipes; no bulk export.
template <class T>
int value_point(lua_State* L) {
  const Held<T> c = geometry_self<T>(L, "point");
  const lua_Integer i = luaL_checkinteger(L, 2);
  if (i < 1 || i > static_cast<lua_Integer>(c->points.size()))
    return luaL_error(L, "point: index %I out of range [1, %I]", i, static_cast<lua_Integer>(c->points.size()));
  push_point(L, c->points[static_cast<std::size_t>(i - 1)]);
  return 1;
}

template <class T>
int value_points(lua_State* L) {
  const Held<T> v = geometry_self<T>(L, "points");
  lua_pushinteger(L, static_cast<lua_Integer>(v->points.size()));
  return 1;
}

// {min = {x, y[, z]}, max = {...}}
template <class T>
int value_bbox(lua_State* L) {
  const Held<T> v = geometry_self<T>(L, "bbox");
  push_bbox(L, v->bbox());
  return 1;
}

void push_names(lua_State* L, const Fields& fields) {
  lua_createtable(L, static_cast<int>(fields.list.size()), 0);
  for (std::size_t i = 0; i < fields.list.size(); ++i) {
    lua_pushstring(L, fields.list[i].name.c_str());
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
}

const Fields& cell_fields(const Polyline& c) { return c.cell_fields; }
const Fields& cell_fields(const Polyline3& c) { return c.cell_fields; }
const Fields& cell_fields(const Mesh& m) { return m.face_fields; }

// v:range(name[, "points" | "cells"]) -> min, max of a field's first component (a develop mesh's tile_class
// runs from 0 to classes - 1), for checks and summaries in recipes. Without the second argument a point field
// is looked for first, then a cell field (a develop mesh has `level` on both).
template <class T>
int value_range(lua_State* L) {
  const Held<T> v = geometry_self<T>(L, "range");
  return call_kernel(L, "range", [&] {
    if (lua_type(L, 2) != LUA_TSTRING || lua_gettop(L) > 3)
      throw Error("takes a field name and optionally \"points\" or \"cells\", v:range(\"level\"), got " +
                  describe(L, 2));
    std::size_t length = 0;
    const char* text = lua_tolstring(L, 2, &length);
    const std::string name(text, length);
    if (name.find('\0') != std::string::npos) throw Error("a field name cannot hold a NUL byte");
    const std::string where = lua_isnoneornil(L, 3) ? "" : text_value(L, 3, "argument 2 of range");
    if (!where.empty() && where != "points" && where != "cells")
      throw Error("argument 2 must be \"points\" or \"cells\", got '" + shown_text(where) + "'");
    const Field* f = where == "cells" ? nullptr : v->point_fields.find(name);
    if (f == nullptr && where != "points") f = cell_fields(*v).find(name);
    if (f == nullptr)
      throw Error("the value has no " + (where.empty() ? std::string() : where.substr(0, where.size() - 1) + " ") +
                  "field '" + shown_text(name) + "'");
    if (f->stored() == 0) throw Error("field '" + shown_text(name) + "' is empty");
    double lo = f->at(0), hi = lo;
    for (std::size_t i = 1; i < f->stored(); ++i) {
      lo = std::min(lo, f->at(i));
      hi = std::max(hi, f->at(i));
    }
    for (double x : {lo, hi})
      if (f->scalar() == Scalar::Int32)
        lua_pushinteger(L, static_cast<lua_Integer>(x));
      else
        lua_pushnumber(L, x);
    return 2;
  });
}

// {points = {names}, cells = {names}}: the fields the value carries (files add arclength and path to curves).
template <class T>
int value_fields(lua_State* L) {
  const Held<T> v = geometry_self<T>(L, "fields");
  lua_createtable(L, 0, 2);
  push_names(L, v->point_fields);
  lua_setfield(L, -2, "points");
  push_names(L, cell_fields(*v));
  lua_setfield(L, -2, "cells");
  return 1;
}

template <class T>
int value_tostring(lua_State* L) {
  const Held<T> v = geometry_self<T>(L, "tostring");
  const std::string s = summary(*v);
  lua_pushlstring(L, s.data(), s.size());
  return 1;
}

}  // namespace

template <class T>
void push_geometry(lua_State* L, T&& value) {
  const std::size_t bytes = value.bytes();
  const double size = budget_size(value);
  push_value(L, ValueType<T>::name, std::move(value), size);
  // Lua only sees the userdata's few bytes; tell its collector about big arrays, so that values a recipe
  // has dropped are freed before the next big one instead of piling up. (Small values are left to the
  // collector's own pace: a step per tiny value costs time in proportion to the whole heap.)
  if (bytes >= (std::size_t{1} << 20))
    lua_gc(L, LUA_GCSTEP, static_cast<int>(std::min<std::size_t>(bytes / 1024, 1 << 30)));
}

template <class T>
void register_geometry(lua_State* L, const std::vector<Method>& own) {
  std::vector<Method> methods{
      {"points", value_points<T>, 0, "no arguments: v:points()"},
      {"point", value_point<T>, 1, "one argument, the point's index: v:point(1)"},
      {"bbox", value_bbox<T>, 0, "no arguments: v:bbox()"},
      {"fields", value_fields<T>, 0, "no arguments: v:fields()"},
      {"range", value_range<T>, 2, "a field name and optionally \"points\" or \"cells\", v:range(\"level\")"},
      {"levels", value_levels, 0, "no arguments: v:levels() (one level: v:level(k))"},
      {"level", value_level, 1, "one level number: v:level(3)"}};
  methods.insert(methods.end(), own.begin(), own.end());  // a type's own method of the same name comes last: it wins
  register_type<T>(L, ValueType<T>::name, methods, value_tostring<T>);
}

template void push_geometry(lua_State*, Polyline&&);
template void push_geometry(lua_State*, Polyline3&&);
template void push_geometry(lua_State*, Mesh&&);
template void register_geometry<Polyline>(lua_State*, const std::vector<Method>&);
template void register_geometry<Polyline3>(lua_State*, const std::vector<Method>&);
template void register_geometry<Mesh>(lua_State*, const std::vector<Method>&);

io::ValueRef AnyValue::ref() const {
  return std::visit([](const auto& h) -> io::ValueRef { return h.get(); }, held);
}

std::size_t AnyValue::points() const {
  return std::visit([](const auto& h) { return h->points.size(); }, held);
}

std::optional<AnyValue> test_any(lua_State* L, int index) {
  if (Held<Polyline> c = test_geometry<Polyline>(L, index)) return AnyValue{c};
  if (Held<Polyline3> c = test_geometry<Polyline3>(L, index)) return AnyValue{c};
  if (Held<Mesh> m = test_geometry<Mesh>(L, index)) return AnyValue{m};
  return std::nullopt;
}

std::string spread_report_advice(lua_State* L, int index, int before, const std::string& into) {
  index = lua_absindex(L, index);
  if (lua_type(L, index) != LUA_TTABLE || lua_type(L, before) != LUA_TUSERDATA) return "";
  if (lua_getmetatable(L, index) != 0) {  // a table with a metatable of its own is not a report
    lua_pop(L, 1);
    return "";
  }
  // Named entries only: no list entry 1, and at least one key.
  const bool listed = lua_rawgeti(L, index, 1) != LUA_TNIL;
  lua_pop(L, 1);
  lua_pushnil(L);
  const bool empty = lua_next(L, index) == 0;
  if (!empty) lua_pop(L, 2);
  if (listed || empty) return "";
  // exclusion.curve and exclusion.surface return { stuck = n, levels = { ... }, ... } after their value.
  auto has = [&](const char* key) {
    const bool present = lua_getfield(L, index, key) != LUA_TNIL;
    lua_pop(L, 1);
    return present;
  };
  // A style without its curve ({ stroke = "red" }) is the recipe's own table, not a report.
  if (has("stroke") || has("stroke_width") || has("fill")) return "";
  std::string call = " to keep its first value only";
  if (has("stuck") && has("levels"))
    call = test_geometry<Mesh>(L, before) ? ", (exclusion.surface{...})" : ", (exclusion.curve{...})";
  return "(the report of a call that returns two values, spread into " + into + "?): wrap the call in parentheses" +
         call;
}

}  // namespace selfsim::interp
