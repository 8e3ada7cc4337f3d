#include "frontend/bindings/transform_options.h"

#include "kernels/base/error.h"

namespace selfsim::interp {

void read_rotation(lua_State* L, Options& o, MeshTransform& t) {
  const int type = o.push("rotate");
  const std::string got = describe(L, -1);
  lua_pop(L, 1);
  if (type != LUA_TNIL && type != LUA_TNUMBER)
    throw Error(
        "option 'rotate' must be degrees about option 'axis' (counterclockwise seen from where it points), "
        "e.g. rotate = 90, axis = {1, 0, 0}, got " +
        got);
  t.degrees = o.number("rotate", 0);
  t.axis = o.point3("axis").value_or(Vec3{0, 0, 1});
}

MeshTransform read_mesh_transform(lua_State* L, Options& o) {
  MeshTransform t;
  if (o.has("mirror"))
    throw Error("option 'mirror' is for curves: a mesh mirrors by a negative scale, e.g. scale = {-1, 1, 1}");
  const int type = o.push("scale");
  const std::string got = describe(L, -1);
  lua_pop(L, 1);
  if (type == LUA_TTABLE) {
    t.scale = *o.point3("scale");
  } else if (type != LUA_TNIL) {
    if (type != LUA_TNUMBER) throw Error("option 'scale' must be a factor or {sx, sy, sz}, got " + got);
    t.scale = Vec3::all(o.number("scale", 1));
  }
  read_rotation(L, o, t);
  t.translate = o.point3("translate").value_or(Vec3{});
  t.validate();
  return t;
}

}  // namespace selfsim::interp
