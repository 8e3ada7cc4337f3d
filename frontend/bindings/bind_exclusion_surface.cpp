// exclusion.surface{ region, start, radius, factor, levels } -> Mesh, report: seed 004's exclusion-radius
// surface (kernels/exclusion/exclusion_surface.h) grown inside a Volume. The start is a Mesh or, for one
// triangle, a table of its three points. The region's boundary is made at a voxel size half the last
// level's radius unless the volume gives one. A thin adapter.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "frontend/bindings/bindings.h"
#include "frontend/bindings/level_reports.h"
#include "frontend/lua/growth.h"
#include "frontend/lua/lua_support.h"
#include "frontend/lua/options_reader.h"
#include "frontend/lua/point_reader.h"
#include "frontend/lua/run_context.h"
#include "frontend/lua/value_types.h"
#include "kernels/base/check.h"
#include "kernels/exclusion/exclusion_surface.h"
#include "kernels/region/level_set.h"
#include "kernels/region/wall_grid.h"

namespace selfsim::interp {

namespace {

// start = mesh, or start = { {x,y,z}, {x,y,z}, {x,y,z} }: one triangle.
Mesh read_start(lua_State* L, Options& o) {
  const int type = o.push("start");
  Mesh m;
  if (const Held<Mesh> given = test_geometry<Mesh>(L, -1)) {
    m = *given;
    m.point_fields = {};
    m.face_fields = {};
  } else if (type == LUA_TTABLE) {
    m.points = read_point_list<Vec3>(L, -1, "option 'start'");
    if (m.points.size() != 3)
      throw Error("option 'start' must be a mesh or the three points of one triangle, got " +
                  std::to_string(m.points.size()) + " points");
    m.triangles = {{0, 1, 2}};
  } else {
    throw Error("option 'start' must be a mesh or the three points of one triangle, got " + describe(L, -1));
  }
  lua_pop(L, 1);
  return m;
}

// { stuck = n, voxel = v, region_triangles = n, walls = "mesh" | "grid", wall_error = e (grid),
//   levels = { { triangles, moves, stuck, seconds, area }, ... } }
void push_report(lua_State* L, const exclusion::SurfaceResult& r, double voxel, std::size_t region_triangles,
                 std::size_t start_triangles, const WallGrid* walls) {
  lua_createtable(L, 0, 6);
  lua_pushstring(L, walls ? "grid" : "mesh");
  lua_setfield(L, -2, "walls");
  if (walls) {
    lua_pushnumber(L, walls->error());
    lua_setfield(L, -2, "wall_error");
  }
  lua_pushinteger(L, static_cast<lua_Integer>(exclusion::total_stuck(r.levels)));
  lua_setfield(L, -2, "stuck");
  lua_pushnumber(L, voxel);
  lua_setfield(L, -2, "voxel");
  lua_pushinteger(L, static_cast<lua_Integer>(region_triangles));
  lua_setfield(L, -2, "region_triangles");
  push_level_reports(L, r.levels, "moves", start_triangles);
  lua_setfield(L, -2, "levels");
}

}  // namespace

int exclusion_surface(lua_State* L) {
  return call_kernel(L, "exclusion.surface", [&] {
    if (lua_gettop(L) != 1 || !lua_istable(L, 1))
      throw Error("takes one table of options, exclusion.surface{ region = ..., start = ..., radius = ... }");
    Options o(L, 1);
    o.require("region", "the volume to fill, e.g. region = volume.box{ min = {0,0,0}, max = {1,1,1} }");
    o.require("start",
              "the start surface, a mesh or one triangle's points, e.g. start = { {0.2,0.2,0.5}, "
              "{0.8,0.2,0.5}, {0.5,0.8,0.5} }");
    o.require("radius", "the first level's exclusion radius, e.g. radius = 0.1");
    o.require("levels", "how many times every triangle is split in four, e.g. levels = 6");
    Held<Volume> region;
    if (o.push("region") != LUA_TNIL) {
      region = test_volume(L, -1);
      if (!region)
        throw Error("option 'region' must be a volume (volume.box{}, volume.sphere{}, volume.mesh(...)), got " +
                    describe(L, -1));
    }
    lua_pop(L, 1);
    const Mesh start = o.has("start") ? read_start(L, o) : Mesh{};
    exclusion::SurfaceOptions opt;
    opt.radius = o.number("radius", opt.radius);
    opt.factor = o.number("factor", opt.factor);
    opt.levels = static_cast<int>(o.integer("levels", 1, 0, 20));
    opt.rule = static_cast<exclusion::SurfaceRule>(o.enumeration("exclusion", {"neighbourhood", "strict"}, 0));
    if (opt.rule == exclusion::SurfaceRule::strict)
      for (const char* name : {"neighbourhood", "near"})
        if (o.has(name))
          throw Error(std::string("option '") + name +
                      "' applies to exclusion = \"neighbourhood\" only (\"strict\" has none)");
    // Any number, math.huge (the whole surface) included, goes to validate(), which names the range.
    const bool number = o.push("neighbourhood") == LUA_TNUMBER;
    const double given = lua_tonumber(L, -1);
    lua_pop(L, 1);
    opt.neighbourhood = number ? given : o.number("neighbourhood", opt.neighbourhood);
    opt.near = o.number("near", opt.near);
    const bool grid_walls = o.enumeration("walls", {"mesh", "grid"}, 0) == 1;
    opt.keep_levels = true;  // f:levels() and growth series need no second run
    o.finish();
    opt.validate();
    // The region resolved finer than the last radius: its boundary then bends less than the radius does.
    const double last = opt.radius * std::pow(opt.factor, std::max(opt.levels - 1, 0));
    const double suggested = last / 2;
    double voxel = region->voxel > 0 ? region->voxel : suggested;
    // Its walls are as fine as the voxels where they come from a grid: a union's or difference's, and any
    // region's with walls = "grid" (a .vdb level set's: its own voxels).
    const bool own_grid = grid_walls && region->samples;
    const double grid_voxel = own_grid ? region->samples->voxel : region->voxel;
    if (grid_voxel > suggested &&
        (grid_walls || (region->kind != Volume::Kind::box && region->kind != Volume::Kind::mesh))) {
      const std::string message =
          recipe_where(L) + "exclusion.surface: the region's voxel size " + number_text(grid_voxel) +
          (own_grid ? " (its .vdb grid's)" : "") + " is coarse for the last level's radius " + number_text(last) +
          " (its boundary is only as fine as a voxel); suggested voxel = " + number_text(suggested);
      lua_warning(L, message.c_str(), 0);
    }
    RunContext& run = RunContext::of(L);
    const Mesh boundary = with_budget(L, [&](const PointBudget& b) { return volume_boundary(*region, voxel, b, run); });
    // walls = "grid": the region's distance grid, resolved twice the first radius deep and no deeper than
    // the middle of the region's box (a point deeper reads as that deep, and takes shorter steps towards far
    // walls; resolving all of a region's inside at a fine voxel takes long).
    const Vec3 extent = region->bbox().size();
    const double depth = std::min(2 * opt.radius, 0.5 * std::min({extent.x, extent.y, extent.z}));
    std::optional<WallGrid> walls;
    if (grid_walls)
      walls = with_budget(L, [&](const PointBudget& b) {
        PointBudget left = b;
        left.held += budget_size(boundary);
        return WallGrid(*region, voxel, depth, left, run);
      });
    exclusion::SurfaceResult r = with_budget(L, [&](const PointBudget& b) {
      opt.budget = b;
      opt.budget.held += budget_size(boundary) + (walls ? WallGrid::size(*region, voxel, depth) : 0);
      return exclusion::exclusion_surface(boundary, start, opt, run, walls ? &*walls : nullptr);
    });
    // A start nearer than the radius to the walls or between its surfaces keeps only that gap there.
    const exclusion::StartGaps& gaps = r.start_gaps;
    const std::string where = recipe_where(L) + "exclusion.surface: ";
    if (std::isfinite(gaps.wall)) {
      const std::string message = where + "start triangle " + std::to_string(gaps.wall_triangle + 1) + " lies " +
                                  number_text(gaps.wall) + " from the region's walls, nearer than the radius " +
                                  number_text(opt.radius) + ": the surface keeps only that gap from them";
      lua_warning(L, message.c_str(), 0);
    }
    if (std::isfinite(gaps.between)) {
      const std::string message = where + "start triangles " + std::to_string(gaps.first + 1) + " and " +
                                  std::to_string(gaps.second + 1) + " of different surfaces lie " +
                                  number_text(gaps.between) + " apart, nearer than the radius " +
                                  number_text(opt.radius) + ": those surfaces keep only that gap";
      lua_warning(L, message.c_str(), 0);
    }
    push_geometry(L, std::move(r.surface));
    // Its levels: the meshes the kernel handed back, as they were after each level.
    double retained = 0;
    for (const Mesh& m : r.steps) retained += budget_size(m);
    auto steps = std::make_shared<const std::vector<Mesh>>(std::move(r.steps));
    attach_growth(L,
                  Growth{0, opt.levels, "level", retained,
                         [steps](int k, const PointBudget& b, Progress&) {
                           const Mesh& m = (*steps)[static_cast<std::size_t>(k)];
                           check_budget(budget_size(m), b, "level " + std::to_string(k));
                           return GrownValue(m);
                         }},
                  retained);
    push_report(L, r, voxel, boundary.triangles.size(), start.triangles.size(), walls ? &*walls : nullptr);
    return 2;
  });
}

}  // namespace selfsim::interp
