// report.levels of an exclusion curve or surface (kernels/exclusion/level_report.h) as a Lua list, one
// table per level: what the curve's and the surface's reports share.
#pragma once

#include <cstddef>
#include <vector>

#include "frontend/lua/lua_support.h"
#include "kernels/exclusion/level_report.h"

namespace selfsim::interp {

// Pushes { { [triangles =,] <splits_name> =, stuck =, seconds = [, area =] }, ... }. `triangles` (start_triangles
// times 4 per level) only when start_triangles is given.
inline void push_level_reports(lua_State* L, const std::vector<exclusion::LevelReport>& levels, const char* splits_name,
                               std::size_t start_triangles = 0) {
  lua_createtable(L, static_cast<int>(levels.size()), 0);
  double triangles = static_cast<double>(start_triangles);
  for (std::size_t i = 0; i < levels.size(); ++i) {
    lua_createtable(L, 0, 4);
    if (start_triangles > 0) {
      triangles *= 4;
      lua_pushinteger(L, static_cast<lua_Integer>(triangles));
      lua_setfield(L, -2, "triangles");
    }
    lua_pushinteger(L, static_cast<lua_Integer>(levels[i].splits));
    lua_setfield(L, -2, splits_name);
    lua_pushinteger(L, static_cast<lua_Integer>(levels[i].stuck));
    lua_setfield(L, -2, "stuck");
    lua_pushnumber(L, levels[i].seconds);
    lua_setfield(L, -2, "seconds");
    if (levels[i].area >= 0) {
      lua_pushnumber(L, levels[i].area);
      lua_setfield(L, -2, "area");
    }
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
}

}  // namespace selfsim::interp
