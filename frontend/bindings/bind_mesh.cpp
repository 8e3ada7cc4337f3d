// Meshes as Lua values: the Mesh type's own methods and mesh{ points, triangles }, a small mesh written in
// a recipe (a start surface or a region later). The methods every value has come from value_types.h.
#include "frontend/bindings/bindings.h"
#include "frontend/bindings/transform_options.h"
#include "frontend/lua/lua_support.h"
#include "frontend/lua/options_reader.h"
#include "frontend/lua/point_reader.h"
#include "frontend/lua/run_context.h"
#include "frontend/lua/value_types.h"
#include "kernels/base/check.h"
#include "kernels/geom/mesh_transform.h"

namespace selfsim::interp {

namespace {

int mesh_faces(lua_State* L) {
  const Held<Mesh> m = geometry_self<Mesh>(L, "faces");
  lua_pushinteger(L, static_cast<lua_Integer>(m->faces()));
  return 1;
}

// m:transform{ scale, rotate, axis, translate } -> a new mesh: scaled about the origin (a factor or one per
// axis; negative mirrors), rotated by degrees about `axis`, then translated (kernels/geom/mesh_transform.h).
int mesh_transform(lua_State* L) {
  const Held<Mesh> m = geometry_self<Mesh>(L, "transform");
  return call_kernel(L, "transform", [&] {
    Options o(L, 2);
    const MeshTransform t = read_mesh_transform(L, o);
    o.finish();
    check_run_budget(L, budget_size(*m), "the transformed copy");
    push_geometry(L, transformed(*m, t.map(), RunContext::of(L)));
    return 1;
  });
}

// The triangles table at index: {i, j, k} of 1-based point indices, counter-clockwise seen from outside.
std::vector<Triangle> read_triangles(lua_State* L, int index, std::size_t points) {
  if (lua_type(L, index) != LUA_TTABLE)
    throw Error("option 'triangles' must be a table of {i, j, k} point indices, got " + describe(L, index));
  const lua_Integer n = list_length(L, index, "option 'triangles'");
  check_run_budget(L, static_cast<double>(n), "option 'triangles'");
  std::vector<Triangle> tris;
  tris.reserve(static_cast<std::size_t>(n));
  for (lua_Integer i = 1; i <= n; ++i) {
    const std::string what = "option 'triangles' entry " + std::to_string(i);
    lua_rawgeti(L, index, i);
    if (lua_type(L, -1) != LUA_TTABLE || lua_rawlen(L, -1) != 3)
      throw Error(what + " must be {i, j, k}, got " + describe(L, -1));
    Triangle t{};
    for (int k = 0; k < 3; ++k) {
      lua_rawgeti(L, -1, k + 1);
      if (!lua_isinteger(L, -1)) throw Error(what + " must hold integer point indices, got " + describe(L, -1));
      t[k] = static_cast<std::uint32_t>(
          check_range(lua_tointeger(L, -1), 1, static_cast<long long>(points), what + " point index") - 1);
      lua_pop(L, 1);
    }
    lua_pop(L, 1);
    tris.push_back(t);
  }
  return tris;
}

int make_mesh(lua_State* L) {
  return call_kernel(L, "mesh", [&] {
    Options o(L, 1);
    o.require("points", "a table of {x, y, z}");
    o.require("triangles", "a table of {i, j, k} point indices, counter-clockwise seen from outside");
    Mesh m;
    m.points = o.points3("points");
    if (o.push("triangles") != LUA_TNIL) m.triangles = read_triangles(L, -1, m.points.size());
    lua_pop(L, 1);
    o.finish();
    if (m.triangles.empty()) throw Error("option 'triangles' must hold at least one triangle");
    m.validate();
    check_run_budget(
        L, budget_size(m),
        "a mesh of " + std::to_string(m.points.size()) + " points and " + std::to_string(m.faces()) + " triangles");
    push_geometry(L, std::move(m));
    return 1;
  });
}

}  // namespace

void open_mesh(lua_State* L) {
  register_geometry<Mesh>(
      L, {{"faces", mesh_faces, 0, "no arguments: m:faces()"},
          {"transform", mesh_transform, 1, "one table: m:transform{ scale, rotate, axis, translate }"}});
  lua_register(L, "mesh", make_mesh);
}

}  // namespace selfsim::interp
