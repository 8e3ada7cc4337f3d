// Reads Mesh:transform's options and solid.orient's `rotate`: one form for both, so a pose written for one
// works in the other. rotate = degrees about `axis` (default {0, 0, 1}), as Curve3:transform takes it;
// scale = s or {sx, sy, sz}; translate = {x, y, z}.
#pragma once

#include "frontend/lua/options_reader.h"
#include "kernels/geom/mesh_transform.h"

namespace selfsim::interp {

// `rotate` and `axis` into t (a rotate given as a table of angles is refused, saying the form).
void read_rotation(lua_State* L, Options& o, MeshTransform& t);

// Every option of Mesh:transform, validated.
MeshTransform read_mesh_transform(lua_State* L, Options& o);

}  // namespace selfsim::interp
