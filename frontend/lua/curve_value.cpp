#include "frontend/lua/curve_value.h"

#include "frontend/lua/lua_support.h"
#include "frontend/lua/point_reader.h"

namespace selfsim::interp {

Polyline to_polyline(lua_State* L, int index, const std::string& what) {
  if (const Held<Polyline> c = test_curve(L, index)) return *c;
  if (lua_type(L, index) != LUA_TTABLE)
    throw Error((what.empty() ? "argument" : what) + " must be a curve or a table of {x, y} points, got " +
                describe(L, index));
  return Polyline::single(read_point_list<Vec2>(L, lua_absindex(L, index), what));
}

Held<Polyline> held_curve(lua_State* L, int index, const std::string& what) {
  if (Held<Polyline> c = test_curve(L, index)) return c;
  return std::make_shared<const Polyline>(to_polyline(L, index, what));
}

}  // namespace selfsim::interp
