// Small geometry from Lua tables: {x, y} and {x, y, z} points and lists of them, checked finite, and
// counted against the run's point budget before they are copied.
#pragma once

#include <lua.hpp>
#include <string>
#include <vector>

#include "kernels/geom/vec2.h"
#include "kernels/geom/vec3.h"

namespace selfsim::interp {

// {x, y} at index; `what` names it in errors ("option 'translate'").
Vec2 read_point2(lua_State* L, int index, const std::string& what);
// {x, y, z} at index.
Vec3 read_point3(lua_State* L, int index, const std::string& what);

// A table of points at index, as V (Vec2 or Vec3); `what` names the table in errors ("option 'points'").
template <class V>
std::vector<V> read_point_list(lua_State* L, int index, const std::string& what);

}  // namespace selfsim::interp
