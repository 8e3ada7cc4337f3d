// save(value, "file.ext", opts?) and param(name, default): the recipe's only ways out and in.
#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <tuple>
#include <vector>

#include "frontend/bindings/bindings.h"
#include "frontend/bindings/print_options.h"
#include "frontend/bindings/save_support.h"
#include "frontend/bindings/style_reader.h"
#include "frontend/lua/growth.h"
#include "frontend/lua/lua_support.h"
#include "frontend/lua/options_reader.h"
#include "frontend/lua/param_spec.h"
#include "frontend/lua/run_context.h"
#include "frontend/lua/value_types.h"
#include "kernels/base/check.h"
#include "kernels/base/lower_case.h"
#include "kernels/io/csv_file.h"
#include "kernels/io/save.h"
#include "kernels/io/text/colour.h"
#include "kernels/io/view/series_file.h"
#include "kernels/region/level_set.h"

namespace selfsim::interp {

namespace {

// SVG renderers (librsvg, browsers) draw in single precision: a curve far from the origin for its size
// comes out blurred or broken even though the file holds every digit. Say so rather than let it look right.
void warn_if_far(lua_State* L, const Polyline& c) {
  const BBox2 b = c.bbox();
  const double size = std::max(b.size().x, b.size().y);
  const double far = largest_coordinate(b);
  if (!(far > 1e5 * size)) return;
  const std::string message = recipe_where(L) + "save: the curve lies " + number_text(far) +
                              " from the origin but is only " + number_text(size) +
                              " across: SVG viewers draw in single precision and may show it broken (move it "
                              "nearer the origin with c:transform{ translate = ... })";
  lua_warning(L, message.c_str(), 0);
}

// STL keeps no shared points: readers (slicers, selfsim's own) merge coinciding corners, so a mesh with two
// points at one place (an unsmoothed developing dragon, whose curves revisit their points) reads back as a
// non-manifold surface. Say so rather than let a slicer find out.
// STL stores single precision: points a float apart or less coincide there too (a solid thickened by 1e-9,
// a fine mesh far from the origin).
void warn_if_coinciding(lua_State* L, const Mesh& m) {
  std::vector<std::array<float, 3>> sorted(m.points.size());
  for (std::size_t i = 0; i < sorted.size(); ++i)
    sorted[i] = {static_cast<float>(m.points[i].x), static_cast<float>(m.points[i].y),
                 static_cast<float>(m.points[i].z)};
  std::sort(sorted.begin(), sorted.end());
  const auto same = std::adjacent_find(sorted.begin(), sorted.end());
  if (same == sorted.end()) return;
  const std::string message = recipe_where(L) + "save: the mesh has points that coincide in single precision (at " +
                              number_text((*same)[0]) + ", " + number_text((*same)[1]) + ", " +
                              number_text((*same)[2]) +
                              "): STL readers merge them and see a non-manifold surface; save as .obj or .ply, or "
                              "separate them (develop's smooth or corner_shift, a larger thickness, a mesh nearer "
                              "the origin)";
  lua_warning(L, message.c_str(), 0);
}

// The rows of a table for .csv: a list of rows, each a list of numbers and strings.
io::CsvRows csv_rows(lua_State* L) {
  if (lua_type(L, 1) != LUA_TTABLE || test_any(L, 1))
    throw Error("a .csv file holds a table of rows, { { \"x\", \"y\" }, { 1, 2 }, ... }, got " + describe(L, 1));
  if (!lua_isnoneornil(L, 3)) throw Error("'.csv' files take no options");
  io::CsvRows rows;
  const lua_Integer n = luaL_len(L, 1);
  if (n < 1) throw Error("a .csv file needs at least one row");
  for (lua_Integer r = 1; r <= n; ++r) {
    lua_geti(L, 1, r);
    if (!lua_istable(L, -1))
      throw Error("row " + std::to_string(r) + " must be a list of numbers or strings, got " + describe(L, -1));
    std::vector<io::CsvCell> row;
    const lua_Integer m = luaL_len(L, -1);
    for (lua_Integer c = 1; c <= m; ++c) {
      lua_geti(L, -1, c);
      if (lua_type(L, -1) == LUA_TNUMBER)
        row.emplace_back(lua_tonumber(L, -1));
      else if (lua_type(L, -1) == LUA_TSTRING)
        row.emplace_back(std::string(lua_tostring(L, -1)));
      else
        throw Error("row " + std::to_string(r) + ", cell " + std::to_string(c) + " must be a number or a string, got " +
                    describe(L, -1));
      lua_pop(L, 1);
    }
    lua_pop(L, 1);
    rows.push_back(std::move(row));
  }
  return rows;
}

// save(volume, "file.ext", opts?): its boundary mesh at the voxel size (a .vdb: the level set of that).
int save_volume(lua_State* L, const Volume& vol) {
  RunContext& run = RunContext::of(L);
  if (lua_type(L, 2) != LUA_TSTRING) throw Error("argument 2 must be a file name, got " + describe(L, 2));
  const std::string name = text_value(L, 2, "argument 2 (the file name)");
  const io::Format* format = io::find_format(lower_case(std::filesystem::path(name).extension().string()));
  if (format == nullptr || !format->holds(io::ValueKind::Mesh)) {
    std::vector<std::string> able;
    for (const io::Format& f : io::formats())
      if (f.holds(io::ValueKind::Mesh)) able.push_back(f.extension);
    throw Error("cannot save a volume as '" + shown_text(std::filesystem::path(name).extension().string()) +
                "', expected one of: " + quoted_list(able));
  }
  io::SaveOptions opt = read_save_options(L, 3, *format);
  check_not_saved(L, name);
  if (opt.voxel == 0) opt.voxel = vol.default_voxel();
  const Mesh boundary = with_budget(L, [&](const PointBudget& b) { return volume_boundary(vol, opt.voxel, b, run); });
  opt.budget = run_budget(L);
  opt.provenance = run_provenance(L, name);
  const std::string written = io::save(&boundary, run.config.out_dir, name, opt, run);
  record_saved(L, name);
  if (is_vtk(*format)) {
    const io::ValueRef ref = &boundary;
    record_view(L, name, io::ViewRole::region, {&ref, 1}, false);
  }
  if (!run.config.quiet)
    std::printf("wrote %s (a volume's boundary: %zu points)\n", shown_text(written, 4096).c_str(),
                boundary.points.size());
  return 0;
}

int save(lua_State* L) {
  return call_kernel(L, "save", [&] {
    RunContext& run = RunContext::of(L);
    if (run.config.params_only) throw Cancelled();  // `selfsim params` writes nothing
    if (lua_type(L, 2) == LUA_TSTRING &&
        lower_case(std::filesystem::path(lua_tostring(L, 2)).extension().string()) == ".csv") {
      const io::CsvRows rows = csv_rows(L);
      const std::string name = text_value(L, 2, "argument 2 (the file name)");
      check_not_saved(L, name);
      const std::string written = io::save_csv(run.config.out_dir, name, rows);
      record_saved(L, name);
      if (!run.config.quiet) std::printf("wrote %s (%zu rows)\n", shown_text(written, 4096).c_str(), rows.size());
      return 0;
    }
    if (lua_type(L, 2) == LUA_TSTRING && io::is_series_name(lua_tostring(L, 2))) return save_series(L);
    if (lua_type(L, 1) == LUA_TTABLE) {  // save({ a, b }, ...): the group of the list
      // A list with times is a series (v:levels()): say so rather than call it a bad group.
      if (lua_getfield(L, 1, "times") != LUA_TNIL)
        throw Error("a list with 'times' is a time series (v:levels()): save it as .pvd or .vtp.series, got '" +
                    shown_text(lua_type(L, 2) == LUA_TSTRING ? lua_tostring(L, 2) : "") + "'");
      lua_pop(L, 1);
      push_group(L, 1, "save({...}, ...)");
      lua_replace(L, 1);
    }
    if (const Held<Volume> vol = test_volume(L, 1)) return save_volume(L, *vol);
    const std::optional<AnyValue> v = test_any(L, 1);
    if (!v) throw Error("argument 1 must be a curve, a mesh, a volume or a list of curves, got " + describe(L, 1));
    if (lua_type(L, 2) != LUA_TSTRING) throw Error("argument 2 must be a file name, got " + describe(L, 2));
    const std::string name = text_value(L, 2, "argument 2 (the file name)");
    const io::Format& format = io::format_for(name, io::kind_of(v->ref()));
    io::SaveOptions opt = read_save_options(L, 3, format);
    check_not_saved(L, name);
    opt.budget = run_budget(L);
    opt.provenance = run_provenance(L, name);
    if (format.extension == ".svg") warn_if_far(L, *std::get<const Polyline*>(v->ref()));
    if (format.extension == ".stl") warn_if_coinciding(L, *std::get<const Mesh*>(v->ref()));
    const std::string written = io::save(v->ref(), run.config.out_dir, name, opt, run);
    record_saved(L, name);
    if (is_vtk(format)) {
      const io::ValueRef ref = v->ref();
      record_view(L, name, role_of(ref), {&ref, 1}, false);
    }
    // Said as each file is committed, in order with the recipe's own print output: when a later error fails
    // the run, the files it did write were already reported.
    if (!run.config.quiet) std::printf("wrote %s (%zu points)\n", shown_text(written, 4096).c_str(), v->points());
    if (!run.config.quiet && (format.extension == ".stl" || format.extension == ".3mf"))
      std::printf("  %s\n", print_summary(L, std::get<Held<Mesh>>(v->held)).c_str());
    return 0;
  });
}

// param(name, default, { min, max, step, choices, doc }): the --set value for name, read with the default's
// type and checked against its range or choices, or the default. The declaration is kept for `selfsim
// params`, sweeps and the studio; one name declared twice must be declared alike.
int param(lua_State* L) {
  return call_kernel(L, "param", [&] {
    RunContext& run = RunContext::of(L);
    const std::string name = text_value(L, 1, "argument 1 (the parameter name)");
    ParamSpec spec = read_param_spec(L, name, 2, 3);
    spec.where = recipe_where(L);
    // results.csv has a column per parameter swept and per result: one name cannot be both (bind_result.cpp).
    if (const auto r = run.result_where.find(name); r != run.result_where.end())
      throw Error("'" + name + "' is the name of a result (given at " + r->second.substr(0, r->second.size() - 2) +
                  "): give the parameter another name");
    const auto [at, first] = run.param_index.try_emplace(name, run.params.size());
    if (first)
      run.params.push_back(spec);
    else if (const ParamSpec& same = run.params[at->second]; !(same == spec))
      throw Error("'" + name + "' is declared again with another default or annotation (first at " +
                  same.where.substr(0, same.where.size() - 2) + ")");
    run.used_params.insert(name);
    const auto it = run.config.sets.find(name);
    if (it == run.config.sets.end()) {
      lua_pushvalue(L, 2);
      return 1;
    }
    push_param_value(L, spec, it->second);
    return 1;
  });
}

}  // namespace

void open_io(lua_State* L) {
  lua_register(L, "save", save);
  lua_register(L, "param", param);
}

}  // namespace selfsim::interp
