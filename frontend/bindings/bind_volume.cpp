// Volumes as Lua values: volume.box{}, volume.sphere{}, volume.mesh(), volume.vdb(), volume.union{},
// volume.difference{}, and the Volume's methods. A thin adapter over kernels/region/volume.h; what a volume becomes at
// a voxel size is level_set.h's.
#include <filesystem>

#include "frontend/bindings/bindings.h"
#include "frontend/bindings/print_options.h"
#include "frontend/lua/lua_support.h"
#include "frontend/lua/options_reader.h"
#include "frontend/lua/run_context.h"
#include "frontend/lua/value_types.h"
#include "kernels/base/check.h"
#include "kernels/base/lower_case.h"
#include "kernels/region/level_set.h"

namespace selfsim::interp {

namespace {

constexpr const char* volume_type = "selfsim.Volume";

void push_volume(lua_State* L, Volume&& v) {
  const double points = v.mesh ? budget_size(*v.mesh) : 0;
  const std::size_t bytes = v.bytes();
  push_value(L, volume_type, std::move(v), points, bytes);
}

// voxel = v: the size every use of the volume takes (a run still warns when it is coarse for its radius).
// 0 when absent.
double read_voxel(Options& o) {
  if (!o.has("voxel")) return 0;
  const double voxel = o.number("voxel", 0);
  if (!(voxel > 0 && voxel < 1e300))
    throw Error("option 'voxel' must be a positive number below 1e300, got " + number_text(voxel));
  return voxel;
}

// Reads `voxel` and refuses options left over, then pushes the volume make() builds with that voxel: the
// end of every constructor that takes an options table.
template <class Make>
int push_made(lua_State* L, Options& o, Make make) {
  const double voxel = read_voxel(o);
  o.finish();
  Volume v = make();
  v.voxel = voxel;
  note_model_box(L, v.bbox());  // a solid this size later is probably still in the region's units
  push_volume(L, std::move(v));
  return 1;
}

Vec3 required_point(Options& o, const char* key, const char* hint) {
  o.require(key, hint);
  return o.point3(key).value_or(Vec3{});
}

int volume_box(lua_State* L) {
  return call_kernel(L, "volume.box", [&] {
    Options o(L, 1);
    const Vec3 lo = required_point(o, "min", "the lowest corner, e.g. min = {0, 0, 0}");
    const Vec3 hi = required_point(o, "max", "the highest corner, e.g. max = {1, 1, 1}");
    return push_made(L, o, [&] { return Volume::box(lo, hi); });
  });
}

int volume_sphere(lua_State* L) {
  return call_kernel(L, "volume.sphere", [&] {
    Options o(L, 1);
    const Vec3 centre = required_point(o, "center", "the centre, e.g. center = {0, 0, 0}");
    o.require("radius", "the radius, e.g. radius = 1");
    const double radius = o.number("radius", 0);
    return push_made(L, o, [&] { return Volume::sphere(centre, radius); });
  });
}

// volume.mesh("file.stl" or a Mesh[, { voxel = v }]): the inside of a closed mesh.
int volume_mesh(lua_State* L) {
  return call_kernel(L, "volume.mesh", [&] {
    Held<Mesh> m = test_geometry<Mesh>(L, 1);
    if (!m && lua_type(L, 1) == LUA_TSTRING) {
      std::variant<Polyline, Polyline3, Mesh> loaded = load_value(L, text_value(L, 1, "argument 1"));
      if (!std::holds_alternative<Mesh>(loaded))
        throw Error("'" + shown_text(lua_tostring(L, 1)) + "' holds a curve, not a closed mesh");
      m = std::make_shared<const Mesh>(std::move(std::get<Mesh>(loaded)));
    }
    if (!m)
      throw Error("argument 1 must be a closed mesh or its file name (.stl, .obj, .ply, .vtp), got " + describe(L, 1));
    double voxel = 0;
    if (!lua_isnoneornil(L, 2)) {
      Options o(L, 2);
      voxel = read_voxel(o);
      o.finish();
    }
    check_run_budget(L, budget_size(*m), "the volume's mesh");
    Volume v = Volume::closed_mesh(*m, RunContext::of(L));
    v.voxel = voxel;
    push_volume(L, std::move(v));
    return 1;
  });
}

// volume.vdb("shape.vdb"[, { grid = name, voxel = v }]): the inside of a level set saved by OpenVDB (Houdini,
// Blender, selfsim): its zero isosurface, meshed by OpenVDB at the grid's own voxels, then a closed mesh
// region as volume.mesh makes one (checked closed and not crossing itself), keeping the level set's voxels.
int volume_vdb(lua_State* L) {
  return call_kernel(L, "volume.vdb", [&] {
    if (lua_type(L, 1) != LUA_TSTRING)
      throw Error("argument 1 must be a .vdb file name in the recipe's folder, got " + describe(L, 1));
    const std::string name = text_value(L, 1, "argument 1");
    if (lower_case(std::filesystem::path(name).extension().string()) != ".vdb")
      throw Error("'" + shown_text(name) + "' is not a .vdb file (for meshes: volume.mesh)");
    std::string grid;
    double voxel = 0;
    if (!lua_isnoneornil(L, 2)) {
      Options o(L, 2);
      grid = o.string("grid", "");
      voxel = read_voxel(o);
      o.finish();
    }
    GridSamples samples;
    Mesh m = std::get<Mesh>(load_value(L, name, grid, &samples));
    Volume v = Volume::closed_mesh(std::move(m), RunContext::of(L));
    v.voxel = voxel;
    if (!samples.index.empty()) {  // a level set: walls = "grid" measures them on it
      v.held_bytes += static_cast<double>(samples.bytes());
      v.samples = std::make_shared<const GridSamples>(std::move(samples));
    }
    push_volume(L, std::move(v));
    return 1;
  });
}

// volume.union{ a, b, ..., voxel = v } and volume.difference{ a, b, ... } (a less the others).
int combine(lua_State* L, const char* fn, Volume::Kind kind) {
  return call_kernel(L, fn, [&] {
    if (lua_type(L, 1) != LUA_TTABLE)
      throw Error(std::string("takes a list of volumes, ") + fn + "{ a, b }, got " + describe(L, 1));
    const auto n = static_cast<lua_Integer>(lua_rawlen(L, 1));
    Options o(L, 1);
    o.positional(n);
    return push_made(L, o, [&] {
      std::vector<std::shared_ptr<const Volume>> parts;
      for (lua_Integer i = 1; i <= n; ++i) {
        lua_rawgeti(L, 1, i);
        Held<Volume> part = test_volume(L, -1);
        if (!part) throw Error("entry " + std::to_string(i) + " must be a volume, got " + describe(L, -1));
        lua_pop(L, 1);
        parts.push_back(std::move(part));
      }
      return Volume::combine(kind, std::move(parts));
    });
  });
}

int volume_union(lua_State* L) { return combine(L, "volume.union", Volume::Kind::unite); }
int volume_difference(lua_State* L) { return combine(L, "volume.difference", Volume::Kind::subtract); }

int volume_bbox(lua_State* L) {
  const Held<Volume> v = check_self<Volume>(L, volume_type, "bbox");
  push_bbox(L, v->bbox());
  return 1;
}

// v:boundary{ voxel = v } -> Mesh: the closed surface a run measures distances to.
int volume_boundary_method(lua_State* L) {
  const Held<Volume> v = check_self<Volume>(L, volume_type, "boundary");
  return call_kernel(L, "boundary", [&] {
    double voxel = v->default_voxel();
    if (!lua_isnoneornil(L, 2)) {
      Options o(L, 2);
      if (const double given = read_voxel(o); given > 0) voxel = given;
      o.finish();
    }
    push_geometry(
        L, with_budget(L, [&](const PointBudget& b) { return volume_boundary(*v, voxel, b, RunContext::of(L)); }));
    return 1;
  });
}

int volume_tostring(lua_State* L) {
  const Held<Volume> v = check_self<Volume>(L, volume_type, "tostring");
  const std::string s = v->summary();
  lua_pushlstring(L, s.data(), s.size());
  return 1;
}

}  // namespace

Held<Volume> test_volume(lua_State* L, int index) { return test_value<Volume>(L, index, volume_type); }

void open_volume(lua_State* L) {
  register_type<Volume>(L, volume_type,
                        {{"bbox", volume_bbox, 0, "no arguments: v:bbox()"},
                         {"boundary", volume_boundary_method, 1, "one table of options: v:boundary{ voxel = 0.02 }"}},
                        volume_tostring);
  const luaL_Reg functions[] = {{"box", volume_box}, {"sphere", volume_sphere}, {"mesh", volume_mesh},
                                {"vdb", volume_vdb}, {"union", volume_union},   {"difference", volume_difference},
                                {nullptr, nullptr}};
  luaL_newlib(L, functions);
  lua_setglobal(L, "volume");
}

}  // namespace selfsim::interp
