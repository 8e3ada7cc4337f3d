// Curves as Lua values, as every binding reads and makes them: pushed, tested, or read from a curve or a table
// of points. The Curve type's own methods and polyline{} / polygon{} are bindings/bind_curve.cpp; the methods
// every value has come from value_types.h.
#pragma once

#include <lua.hpp>
#include <string>

#include "frontend/lua/value_types.h"
#include "kernels/geom/polyline.h"

namespace selfsim::interp {

// Pushes a new Curve; kernels guarantee it is finite (they check their results), and its points count
// against the run's budget while it lives.
inline void push_curve(lua_State* L, Polyline&& c) { push_geometry(L, std::move(c)); }
// The curve at index, or null if the value is not a curve; hold it for as long as it is used.
inline Held<Polyline> test_curve(lua_State* L, int index) { return test_geometry<Polyline>(L, index); }
// A curve userdata, or a table of {x, y} points read as one open path. Throws Error naming `what`.
Polyline to_polyline(lua_State* L, int index, const std::string& what);
// The same without copying a curve: the value itself, held for the call (a curve of a hundred million
// points is not duplicated to be read), or a new one read from a table.
Held<Polyline> held_curve(lua_State* L, int index, const std::string& what);

}  // namespace selfsim::interp
