#include "frontend/lua/point_reader.h"

#include "frontend/lua/lua_support.h"
#include "frontend/lua/options_reader.h"

namespace selfsim::interp {

namespace {

// A value given where a point was wanted, for the message: "a 2D point {1, 2}" (where a 3D one was
// wanted, or the reverse), "a list of 4 numbers", "a list of 3 points", or describe()'s words.
std::string described_point(lua_State* L, int index) {
  if (lua_type(L, index) != LUA_TTABLE || lua_getmetatable(L, index) != 0) {
    if (lua_type(L, index) == LUA_TTABLE) lua_pop(L, 1);
    return describe(L, index);
  }
  const lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, index));
  if (n == 0) {
    const bool named = lua_getfield(L, index, "x") != LUA_TNIL;
    lua_pop(L, 1);
    return named ? "a table of named coordinates (a point lists them in order, without names)" : "an empty table";
  }
  lua_rawgeti(L, index, 1);
  const bool list_of_tables = lua_type(L, -1) == LUA_TTABLE;
  lua_pop(L, 1);
  if (list_of_tables) return "a list of " + std::to_string(n) + (n == 1 ? " point" : " points");
  std::string numbers;
  for (lua_Integer i = 1; i <= n && i <= 64; ++i) {
    const bool number = lua_rawgeti(L, index, i) == LUA_TNUMBER;
    if (number && i <= 3) numbers += (i == 1 ? "" : ", ") + describe(L, -1);
    lua_pop(L, 1);
    if (!number) return "a list of " + std::to_string(n) + (n == 1 ? " value" : " values");
  }
  if (n == 2 || n == 3) return std::string(n == 2 ? "a 2D" : "a 3D") + " point {" + numbers + "}";
  return "a list of " + std::to_string(n) + (n == 1 ? " number" : " numbers");
}

// The n numbers of the table at index into xs, checked finite.
void read_numbers(lua_State* L, int index, int n, double* xs, const std::string& what, const char* shape) {
  index = lua_absindex(L, index);
  if (lua_type(L, index) != LUA_TTABLE || lua_rawlen(L, index) != static_cast<lua_Unsigned>(n))
    throw Error(what + " must be " + (n == 2 ? "a 2D point " : "a 3D point ") + shape + ", got " +
                described_point(L, index));
  static const char* axis[] = {" x", " y", " z"};
  for (int k = 0; k < n; ++k) {
    lua_rawgeti(L, index, k + 1);
    xs[k] = finite_number(L, -1, what + axis[k]);
    lua_pop(L, 1);
  }
}

Vec2 read_point(lua_State* L, int index, const std::string& what, Vec2*) { return read_point2(L, index, what); }
Vec3 read_point(lua_State* L, int index, const std::string& what, Vec3*) { return read_point3(L, index, what); }

}  // namespace

Vec2 read_point2(lua_State* L, int index, const std::string& what) {
  double xs[2];
  read_numbers(L, index, 2, xs, what, "{x, y}");
  return {xs[0], xs[1]};
}

Vec3 read_point3(lua_State* L, int index, const std::string& what) {
  double xs[3];
  read_numbers(L, index, 3, xs, what, "{x, y, z}");
  return {xs[0], xs[1], xs[2]};
}

template <class V>
std::vector<V> read_point_list(lua_State* L, int index, const std::string& what) {
  index = lua_absindex(L, index);
  const char* shape = sizeof(V) == sizeof(Vec2) ? "{x, y}" : "{x, y, z}";
  if (lua_type(L, index) != LUA_TTABLE)
    throw Error(what + " must be a table of " + shape + " points, got " + describe(L, index));
  const lua_Integer n = list_length(L, index, what.empty() ? "the table of points" : what);
  check_run_budget(L, static_cast<double>(n), what.empty() ? "a table of points" : what);  // before copying
  std::vector<V> pts;
  pts.reserve(static_cast<std::size_t>(n));
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_rawgeti(L, index, i);
    pts.push_back(
        read_point(L, -1, (what.empty() ? "" : what + " ") + "point " + std::to_string(i), static_cast<V*>(nullptr)));
    lua_pop(L, 1);
  }
  return pts;
}

template std::vector<Vec2> read_point_list(lua_State*, int, const std::string&);
template std::vector<Vec3> read_point_list(lua_State*, int, const std::string&);

}  // namespace selfsim::interp
