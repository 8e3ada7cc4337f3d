// The Lua value types of geometry (Curve, Curve3, Mesh) in one registry, so that save(), the methods every
// value has (:points(), :bbox(), :fields(), tostring) and the budget accounting are written once for all
// of them. A value's size (points, plus faces for a mesh) counts against --max-points while it lives.
#pragma once

#include <lua.hpp>
#include <optional>
#include <variant>
#include <vector>

#include "frontend/lua/lua_support.h"
#include "kernels/geom/mesh.h"
#include "kernels/geom/polyline.h"
#include "kernels/io/format.h"

namespace selfsim::interp {

template <class T>
struct ValueType;
template <>
struct ValueType<Polyline> {
  static constexpr const char* name = "selfsim.Curve";
};
template <>
struct ValueType<Polyline3> {
  static constexpr const char* name = "selfsim.Curve3";
};
template <>
struct ValueType<Mesh> {
  static constexpr const char* name = "selfsim.Mesh";
};

// What a value counts against --max-points: its points, and a mesh's faces too.
inline double budget_size(const Polyline& c) { return static_cast<double>(c.points.size()); }
inline double budget_size(const Polyline3& c) { return static_cast<double>(c.points.size()); }
inline double budget_size(const Mesh& m) { return static_cast<double>(m.points.size() + m.faces()); }

// Pushes a new value (kernels guarantee it is finite: they check their results).
template <class T>
void push_geometry(lua_State* L, T&& value);

// The value of type T at index, or null; hold it for as long as it is used.
template <class T>
Held<T> test_geometry(lua_State* L, int index) {
  return test_value<T>(L, index, ValueType<T>::name);
}

// A method's receiver of type T (see check_self); hold it for the whole call.
template <class T>
Held<T> geometry_self(lua_State* L, const char* method) {
  return check_self<T>(L, ValueType<T>::name, method);
}

// Any geometry value, held for the call.
struct AnyValue {
  std::variant<Held<Polyline>, Held<Polyline3>, Held<Mesh>> held;

  io::ValueRef ref() const;
  // Points, for the run's summary.
  std::size_t points() const;
};

// The geometry value at index, or nothing if it is not one.
std::optional<AnyValue> test_any(lua_State* L, int index);

// Lua spreads every result of a call that ends a table constructor or an argument list, so
// group{ a, exclusion.curve{...} } holds a, the curve and its report. When the value at `index` is a table
// of named entries only (a report, not a list or a styled member) and a value (userdata) comes just before
// it at `before`, returns the advice for the message, naming the call when the table is a report selfsim
// knows ("(the report of a call that returns two values, spread into group{...}?): wrap the call in
// parentheses, (exclusion.curve{...})"); otherwise "". `into` names the list: "group{...}", "concat(...)".
std::string spread_report_advice(lua_State* L, int index, int before, const std::string& into);

// Registers T's metatable with the common methods and T's own.
template <class T>
void register_geometry(lua_State* L, const std::vector<Method>& own);

// {x, y} or {x, y, z} as a new Lua table.
void push_point(lua_State* L, Vec2 p);
void push_point(lua_State* L, Vec3 p);
// {min = {...}, max = {...}}
template <class V>
void push_bbox(lua_State* L, const BBox<V>& b);

}  // namespace selfsim::interp
