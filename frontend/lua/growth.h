// How a value grew, level by level, so that a recipe takes its levels from the finished value without a run
// of its own (v:levels(), v:level(k)) and saves them as a ParaView time series in one line:
//   save(f:levels(), "growth.pvd")
// A binding whose kernel grows by levels attaches a Growth to the value it returns: a way to make the value
// as it was at each level, from what the kernel handed back (the exclusion surface's meshes after each
// level), from the final value (the exclusion curve's points up to a level) or by the kernel at that level
// (an L-system's curve, hoisting's generations, a developing surface's first levels). Kernels stay free of
// Lua; a Growth only calls them.
#pragma once

#include <functional>
#include <lua.hpp>
#include <string>
#include <variant>

#include "kernels/base/budget.h"
#include "kernels/base/progress.h"
#include "kernels/geom/mesh.h"
#include "kernels/geom/polyline.h"

namespace selfsim::interp {

using GrownValue = std::variant<Polyline, Polyline3, Mesh>;

struct Growth {
  int first = 0, last = 0;     // the levels there are; the value itself is the last
  std::string unit = "level";  // what a level is called: "level", "generation"
  double kept = 0;             // budget points of what `at` keeps alive (earlier meshes, a stack, the value)
  // The value at level k, first <= k < last (the last is the value itself), within `budget`.
  std::function<GrownValue(int k, const PointBudget& budget, Progress& progress)> at;
};

// Records how the value on top of the stack (just pushed by push_geometry) grew. `retained` is what the
// growth keeps alive beyond the value itself (earlier levels' meshes, a stack's curves), in budget points:
// checked against, and counted in, --max-points with the value. A level taken from the value holds all of
// growth.kept, the value included if `at` uses it.
void attach_growth(lua_State* L, Growth growth, double retained = 0);

// Whether the value at index is a geometry value that knows its levels.
bool has_growth(lua_State* L, int index);
// Pushes { v0, v1, ..., times = { first, ..., last } }: the levels of the value at index (which is the last).
// Throws Error when it has none.
void push_levels(lua_State* L, int index);

// v:levels() (push_levels) and v:level(k) -> the value at level k: methods of every geometry value.
int value_levels(lua_State* L);
int value_level(lua_State* L);

}  // namespace selfsim::interp
