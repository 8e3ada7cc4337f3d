// One entry point per kernel family's binding file; each registers its globals and types.
#pragma once

#include <lua.hpp>
#include <string>
#include <variant>

#include "frontend/lua/lua_support.h"
#include "kernels/geom/polyline.h"
#include "kernels/geom/vec2.h"
#include "kernels/geom/vec3.h"
#include "kernels/region/volume.h"

namespace selfsim::lsystem {
struct Grammar;
}

namespace selfsim::interp {

void open_curve(lua_State* L);       // bind_curve.cpp: Curve, polyline{}, polygon{}
void open_mesh(lua_State* L);        // bind_mesh.cpp: Mesh, mesh{}
void open_lsystem(lua_State* L);     // bind_lsystem.cpp: lsystem{}
void open_substitute(lua_State* L);  // bind_substitute.cpp: substitute{}
void open_io(lua_State* L);          // bind_io.cpp: save(), param()
void open_result(lua_State* L);      // bind_result.cpp: result()
void open_load(lua_State* L);        // bind_load.cpp: load()
void open_group(lua_State* L);       // bind_group.cpp: group{}, concat()
void open_hoist(lua_State* L);       // bind_hoist.cpp: bspline{}, catmull_rom{}, hoist.*, simplify()
void open_develop(lua_State* L);     // bind_develop.cpp: develop()
void open_exclusion(lua_State* L);   // bind_exclusion.cpp: exclusion.curve{}
void open_analysis(lua_State* L);    // bind_analysis.cpp: dimension()
void open_volume(lua_State* L);      // bind_volume.cpp: Volume, volume.box{} and the rest
void open_solid(lua_State* L);       // bind_solid.cpp: solid.thicken, solid.check and the rest
// Called by open_solid with the `solid` table on top of the stack: each adds its functions to it.
void add_solid_placing(lua_State* L);  // bind_solid_place.cpp: solid.place, solid.orient
void add_solid_union(lua_State* L);    // bind_solid_union.cpp: solid.union, solid.difference

// bind_lsystem.cpp: the grammar at index, or null (develop() takes one as its source).
Held<lsystem::Grammar> test_grammar(lua_State* L, int index);
// bind_exclusion_surface.cpp: exclusion.surface{}, registered by open_exclusion.
int exclusion_surface(lua_State* L);
// bind_volume.cpp: the Volume at index, or null.
Held<Volume> test_volume(lua_State* L, int index);
// bind_load.cpp: what load(name) reads, checked against the run's budget but not yet pushed.
// `grid`: for a .vdb, the grid whose surface to take (else its first level set).
std::variant<Polyline, Polyline3, Mesh> load_value(lua_State* L, const std::string& name, const std::string& grid = "",
                                                   GridSamples* samples = nullptr);
// bind_group.cpp: pushes group{...} of the list at index (save({ a, b }, ...) uses it too, naming the list
// `into` in messages).
void push_group(lua_State* L, int index, const char* into = "group{...}");
// bind_group.cpp: c:reverse() for Curve (V = Vec2) and Curve3 (Vec3).
template <class V>
int curve_reverse(lua_State* L);
// bind_develop.cpp: c:rounded{...}, a curve's corners rounded by arcs.
int curve_rounded(lua_State* L);

inline void open_all(lua_State* L) {
  open_curve(L);
  open_mesh(L);
  open_lsystem(L);
  open_substitute(L);
  open_io(L);
  open_result(L);
  open_load(L);
  open_group(L);
  open_hoist(L);
  open_develop(L);
  open_exclusion(L);
  open_analysis(L);
  open_volume(L);
  open_solid(L);
}

}  // namespace selfsim::interp
