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

#include "interpreter/bindings.h"
#include "interpreter/growth.h"
#include "interpreter/lua_support.h"
#include "interpreter/options_reader.h"
#include "interpreter/parse_text.h"
#include "interpreter/run_context.h"
#include "interpreter/style_reader.h"
#include "interpreter/value_types.h"
#include "kernels/geom/check.h"
#include "kernels/geom/level_set.h"
#include "kernels/geom/lower_case.h"
#include "kernels/io/colour.h"
#include "kernels/io/csv_file.h"
#include "kernels/io/save.h"
#include "kernels/io/series_file.h"

namespace selfsim::interp {

namespace {

// The save() options of format f, read by type; an option of another format is named as such, and any
// other unknown key gets Options' "did you mean" among f's own options.
io::SaveOptions read_save_options(lua_State* L, int index, const io::Format& f) {
  Options o(L, index);
  io::SaveOptions s;
  auto has = [&](const char* name) { return std::find(f.options.begin(), f.options.end(), name) != f.options.end(); };
  if (has("stroke")) {  // the style options: one value each, or a palette cycled over a group's members
    StyleOptions style = read_style(L, o, true);
    // Given options override the style a curve carries in its fields (curve_style.h), so they are recorded.
    auto take = [&](auto& from, auto& to, const char* name) {
      if (from.empty()) return;
      to = std::move(from);
      s.given.push_back(name);
    };
    take(style.stroke, s.stroke, "stroke");
    take(style.stroke_width, s.stroke_width, "stroke_width");
    take(style.fill, s.fill, "fill");
  }
  // size = 800 (pixels) or size = "150mm" (also cm, in): a physical size for plotters.
  if (has("size")) {
    const int type = o.push("size");
    if (type == LUA_TSTRING) {
      const std::string text = text_value(L, -1, "option 'size'");
      std::size_t digits = 0;
      while (digits < text.size() && (std::isdigit(static_cast<unsigned char>(text[digits])) || text[digits] == '.'))
        ++digits;
      const auto value = parse_text<double>(text.substr(0, digits));
      if (!value)
        throw Error("option 'size' must be a number of pixels or a length such as \"150mm\", got '" + shown_text(text) +
                    "'");
      s.size = *value;
      s.size_unit = text.substr(digits);
    } else if (type != LUA_TNIL) {
      s.size = finite_number(L, -1, "option 'size'");
    }
    lua_pop(L, 1);
  }
  // With a physical size the stroke width is a pen's, in that unit: 0.3 mm unless given (1 mm would be a
  // marker, 1 in a blob).
  if (!s.size_unit.empty() && std::find(s.given.begin(), s.given.end(), "stroke_width") == s.given.end())
    s.stroke_width = {s.size_unit == "mm" ? 0.3 : s.size_unit == "cm" ? 0.03 : 0.3 / 25.4};
  if (has("voxel") && o.has("voxel")) {
    s.voxel = o.number("voxel", 0);
    if (!(s.voxel > 0)) throw Error("option 'voxel' must be a positive number, got " + number_text(s.voxel));
  }
  io::check_options(f, o.unread());
  o.finish();
  return s;
}

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

// Saving two values under one name would silently keep the last: the second save is an error naming the
// line of the first, and the first file stays as it was. Two names are one output when they are the same
// path inside the output folder once made lexically normal ("./a.svg", "sub//a.svg"), or when the second
// opens the very file the first wrote: "A.svg" after "a.svg" where the filesystem ignores case (macOS,
// Windows), though not on Linux, where they are two files.
std::string normal_name(const std::string& name) {
  std::string normal = std::filesystem::path(name).lexically_normal().generic_string();
  while (normal.size() > 1 && normal.back() == '/') normal.pop_back();
  return normal;
}

// The identity of the file `name` names in the output folder, if there is one (a link is not followed).
std::optional<std::pair<unsigned long long, unsigned long long>> file_identity(const RunContext& run,
                                                                               const std::string& name) {
  struct stat st {};
  if (::lstat((run.config.out_dir / name).c_str(), &st) != 0) return std::nullopt;
  return std::pair<unsigned long long, unsigned long long>{st.st_dev, st.st_ino};
}

// "line 3 of this run", or "helper.lua:3 in this run" for a save in another file, from locations such as
// "dragon.lua:3: ".
std::string earlier_line(const std::string& earlier, const std::string& now) {
  auto split = [](const std::string& where) {
    const std::string trimmed = where.substr(0, where.size() >= 2 ? where.size() - 2 : 0);
    const std::size_t colon = trimmed.rfind(':');
    if (colon == std::string::npos) return std::pair<std::string, std::string>{trimmed, ""};
    return std::pair<std::string, std::string>{trimmed.substr(0, colon), trimmed.substr(colon + 1)};
  };
  const auto [file, line] = split(earlier);
  if (line.empty()) return "an earlier save of this run";
  if (earlier == now) return "this same line earlier in the run (in a loop? put the loop's variable in the name)";
  if (file == split(now).first) return "line " + line + " of this run";
  return file + ":" + line + " in this run";
}

// Throws Error when this run has already written the file `name` names.
void check_not_saved(lua_State* L, const std::string& name) {
  const RunContext& run = RunContext::of(L);
  auto it = run.saved.find(normal_name(name));
  bool same_file = false;  // found by the file's identity, not by its name
  if (it == run.saved.end()) {
    const auto id = file_identity(run, name);
    const auto file = id ? run.saved_files.find(*id) : run.saved_files.end();
    if (file == run.saved_files.end()) return;
    it = run.saved.find(file->second);
    if (it == run.saved.end()) return;
    same_file = true;
  }
  const auto& [first_name, first_where] = it->second;
  const std::string as = first_name == name ? ""
                         : same_file        ? " (as '" + shown_text(first_name) + "', the same file here)"
                                            : " (as '" + shown_text(first_name) + "')";
  throw Error("'" + shown_text(name) + "' was already written by " + earlier_line(first_where, recipe_where(L)) + as +
              "; give another name");
}

// Records a file written by save().
void record_saved(lua_State* L, const std::string& name) {
  RunContext& run = RunContext::of(L);
  const std::string normal = normal_name(name);
  run.saved.try_emplace(normal, name, recipe_where(L));
  if (const auto id = file_identity(run, name)) run.saved_files.insert_or_assign(*id, normal);
}

// Whether every point of v lies in the plane z = 0 (a 2D curve does by construction).
bool flat(const io::ValueRef& v) {
  return std::visit(
      [](const auto* value) {
        if constexpr (std::is_same_v<std::decay_t<decltype(*value)>, Polyline>) {
          return true;
        } else {
          return std::all_of(value->points.begin(), value->points.end(), [](const Vec3& p) { return p.z == 0; });
        }
      },
      v);
}

// Records a VTK file or series written, for the run's ParaView view.
void record_view(lua_State* L, const std::string& name, io::ViewRole role, std::span<const io::ValueRef> steps,
                 bool series) {
  io::ViewDataset d;
  d.file = normal_name(name);
  // The file's name without the extension that made it: "growth" for growth.pvd and growth.vtp.series.
  d.name = std::filesystem::path(name).filename().string();
  for (const char* ext : {".pvd", ".vtp.series", ".vtu.series", ".vtp", ".vtu"})
    if (const std::string e = ext;
        d.name.size() > e.size() && lower_case(d.name.substr(d.name.size() - e.size())) == e) {
      d.name.erase(d.name.size() - e.size());
      break;
    }
  d.role = role;
  d.series = series;
  d.flat = std::all_of(steps.begin(), steps.end(), flat);
  if (role != io::ViewRole::region) d.colouring = io::series_colouring(steps);
  RunContext::of(L).view_datasets.push_back(std::move(d));
}

bool is_vtk(const io::Format& f) { return f.extension == ".vtp" || f.extension == ".vtu"; }

io::ViewRole role_of(const io::ValueRef& v) {
  return std::holds_alternative<const Mesh*>(v) ? io::ViewRole::surface : io::ViewRole::curve;
}

// save(list or value, "growth.pvd" or "growth.vtp.series", opts?): a ParaView time series, one step per
// entry of the list (times from its `times`, else 0, 1, ...); a value that grew by levels saves its levels.
int save_series(lua_State* L) {
  RunContext& run = RunContext::of(L);
  const std::string name = text_value(L, 2, "argument 2 (the file name)");
  if (has_growth(L, 1)) {  // a value that grew: its levels
    push_levels(L, 1);
    lua_replace(L, 1);
  } else if (test_any(L, 1)) {  // any other value: a series of one step
    lua_createtable(L, 1, 0);
    lua_pushvalue(L, 1);
    lua_rawseti(L, -2, 1);
    lua_replace(L, 1);
  }
  if (lua_type(L, 1) != LUA_TTABLE)
    throw Error("a series holds a list of curves or meshes (v:levels(), or { a, b, c }), got " + describe(L, 1));
  // The list's entries; its one named key may be `times`.
  const auto n = static_cast<lua_Integer>(lua_rawlen(L, 1));
  lua_pushnil(L);
  while (lua_next(L, 1) != 0) {
    lua_pop(L, 1);
    const bool listed = lua_isinteger(L, -1) && lua_tointeger(L, -1) >= 1 && lua_tointeger(L, -1) <= n;
    if (!listed && !(lua_type(L, -1) == LUA_TSTRING && std::string_view(lua_tostring(L, -1)) == "times"))
      throw Error("a series is a list of curves or meshes with an optional 'times', got the key " + describe(L, -1));
  }
  if (n < 1) throw Error("a series needs at least one curve or mesh");
  std::vector<AnyValue> held;
  std::vector<io::SeriesStep> steps;
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_rawgeti(L, 1, i);
    std::optional<AnyValue> v = test_any(L, -1);
    if (!v)
      throw Error("entry " + std::to_string(i) + " of the series must be a curve or mesh, got " + describe(L, -1));
    lua_pop(L, 1);
    steps.push_back({v->ref(), static_cast<double>(i - 1)});
    held.push_back(std::move(*v));
  }
  if (lua_getfield(L, 1, "times") != LUA_TNIL) {
    if (!lua_istable(L, -1))
      throw Error("the series' 'times' must be a list of " + std::to_string(n) + " numbers, one per entry, got " +
                  describe(L, -1) + " (not a list)");
    const lua_Integer count = list_length(L, -1, "the series' 'times'");
    if (count != n)
      throw Error("the series' 'times' must be a list of " + std::to_string(n) + " numbers, one per entry, got " +
                  std::to_string(count));
    for (lua_Integer i = 1; i <= n; ++i) {
      lua_rawgeti(L, -1, i);
      steps[static_cast<std::size_t>(i - 1)].time = finite_number(L, -1, "entry " + std::to_string(i) + " of 'times'");
      lua_pop(L, 1);
    }
  }
  lua_pop(L, 1);
  io::SaveOptions opt = read_save_options(L, 3, *io::find_format(io::series_step_extension(name)));
  check_not_saved(L, name);
  // A curve that draws nothing at a level (a plant's axiom "X" at level 0) has no file to be: the series
  // starts at its first level that has one, each step keeping its time.
  std::erase_if(steps, [](const io::SeriesStep& s) {
    return std::visit([](const auto* v) { return v->points.empty(); }, s.value);
  });
  if (steps.empty()) throw Error("every entry of the series is empty: there is nothing to draw");
  const std::vector<std::string> step_names = io::series_step_names(name, steps.size());
  for (const std::string& step : step_names) {
    try {
      check_not_saved(L, step);
    } catch (const Error& e) {
      throw Error("'" + shown_text(name) + "' would write its steps into the folder of '" + shown_text(step) +
                  "' (a .pvd and a .vtp.series of one name share it): " + e.what());
    }
  }
  opt.budget = run_budget(L);
  const io::SeriesFiles written = io::save_series(steps, run.config.out_dir, name, opt, run);
  for (const std::string& step : step_names) record_saved(L, step);
  record_saved(L, name);
  std::vector<io::ValueRef> refs;
  for (const io::SeriesStep& s : steps) refs.push_back(s.value);
  record_view(L, name, role_of(refs.back()), refs, true);
  if (!run.config.quiet)
    std::printf("wrote %s (%zu step%s, %s%s%s; %zu points in the last)\n", shown_text(written.series, 4096).c_str(),
                steps.size(), steps.size() == 1 ? "" : "s", shown_text(written.steps.front(), 4096).c_str(),
                steps.size() == 1 ? "" : " ... ",
                steps.size() == 1 ? "" : shown_text(written.steps.back(), 4096).c_str(),
                std::visit([](const auto* v) { return v->points.size(); }, steps.back().value));
  return 0;
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
    return 0;
  });
}

// param(name, default): the --set value for name, read with the default's type, or the default.
int param(lua_State* L) {
  return call_kernel(L, "param", [&] {
    RunContext& run = RunContext::of(L);
    const std::string name = text_value(L, 1, "argument 1 (the parameter name)");
    const int type = lua_type(L, 2);
    if (type != LUA_TNUMBER && type != LUA_TSTRING && type != LUA_TBOOLEAN)
      throw Error("default of '" + name + "' must be a number, string or boolean, got " + describe(L, 2));
    run.used_params.insert(name);
    const auto it = run.config.sets.find(name);
    if (it == run.config.sets.end()) {
      lua_pushvalue(L, 2);
      return 1;
    }
    const std::string& text = it->second;
    if (type == LUA_TSTRING) {
      lua_pushlstring(L, text.data(), text.size());
    } else if (type == LUA_TBOOLEAN) {
      if (text != "true" && text != "false") throw Error("--set " + name + "=" + text + ": expected true or false");
      lua_pushboolean(L, text == "true");
    } else if (const auto whole = parse_text<long long>(text)) {
      lua_pushinteger(L, *whole);  // a number default takes any number: integers stay integers
    } else {
      const auto v = parse_text<double>(text);
      if (!v) throw Error("--set " + name + "=" + text + ": expected a finite number");
      lua_pushnumber(L, *v);
    }
    return 1;
  });
}

}  // namespace

void open_io(lua_State* L) {
  lua_register(L, "save", save);
  lua_register(L, "param", param);
}

}  // namespace selfsim::interp
