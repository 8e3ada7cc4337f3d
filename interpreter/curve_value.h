// Curves as Lua values: a userdata holding a Polyline, with methods; and small paths read from tables.
#pragma once

#include <lua.hpp>
#include <memory>
#include <string>

#include "kernels/geom/polyline.h"

namespace selfsim::interp {

inline constexpr const char* curve_type = "selfsim.Curve";

// Pushes a new Curve; kernels guarantee it is finite (they check their results), and its points count
// against the run's budget while it lives.
void push_curve(lua_State* L, Polyline&& c);
// The curve at index, or null if the value is not a curve; hold it for as long as it is used.
std::shared_ptr<const Polyline> test_curve(lua_State* L, int index);
// A curve userdata, or a table of {x, y} points read as one open path. Throws Error naming `what`.
Polyline to_polyline(lua_State* L, int index, const std::string& what);

// Registers the Curve type and the polyline{} / polygon{} constructors.
void open_curve(lua_State* L);

}  // namespace selfsim::interp
