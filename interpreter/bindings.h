// One entry point per kernel family's binding file; each registers its globals and types.
#pragma once

#include <lua.hpp>

namespace selfsim::interp {

void open_curve(lua_State* L);       // curve_value.cpp: Curve, polyline{}, polygon{}
void open_mesh(lua_State* L);        // mesh_value.cpp: Mesh, mesh{}
void open_lsystem(lua_State* L);     // bind_lsystem.cpp: lsystem{}
void open_substitute(lua_State* L);  // bind_substitute.cpp: substitute{}
void open_io(lua_State* L);          // bind_io.cpp: save(), param()
void open_load(lua_State* L);        // bind_load.cpp: load()

inline void open_all(lua_State* L) {
  open_curve(L);
  open_mesh(L);
  open_lsystem(L);
  open_substitute(L);
  open_io(L);
  open_load(L);
}

}  // namespace selfsim::interp
