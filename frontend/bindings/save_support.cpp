#include "frontend/bindings/save_support.h"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <optional>

#include "frontend/bindings/style_reader.h"
#include "frontend/lua/lua_support.h"
#include "frontend/lua/options_reader.h"
#include "frontend/lua/parse_text.h"
#include "frontend/lua/run_context.h"
#include "kernels/base/check.h"
#include "kernels/base/lower_case.h"
#include "kernels/io/provenance/provenance.h"
#include "kernels/io/view/natural_field.h"
#include "kernels/io/view/up_axis.h"

namespace selfsim::interp {

// The save() options of format f, read by type; an option of another format is named as such, and any
// other unknown key gets Options' "did you mean" among f's own options.
std::string run_provenance(lua_State* L, const std::string& name) {
  RunContext& run = RunContext::of(L);
  io::Provenance p;
  p.version = SELFSIM_VERSION;
  std::error_code ec;
  p.recipe = std::filesystem::absolute(run.config.recipe, ec).lexically_normal().string();
  p.sha256 = run.recipe_sha256;
  p.sets = run.config.sets;
  p.seed = run.config.seed;
  p.name = std::filesystem::path(name).lexically_normal().generic_string();
  return io::provenance_json(p);
}

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
  if (has("name") && o.has("name")) {
    s.name = o.string("name", "");
    if (s.name.empty() || s.name.size() > 256)
      throw Error("option 'name' must be a name of 1 to 256 characters, got '" + shown_text(s.name) + "'");
  }
  s.application = std::string("selfsim ") + SELFSIM_VERSION;
  io::check_options(f, o.unread());
  o.finish();
  return s;
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
namespace {

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

}  // namespace

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

namespace {

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

}  // namespace

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
  if (!steps.empty()) d.up = io::up_axis(steps.back());  // the grown result's up, as preview takes it
  if (role != io::ViewRole::region) d.colouring = io::series_colouring(steps, RunContext::of(L));
  RunContext::of(L).view_datasets.push_back(std::move(d));
}

bool is_vtk(const io::Format& f) { return f.extension == ".vtp" || f.extension == ".vtu"; }

io::ViewRole role_of(const io::ValueRef& v) {
  return std::holds_alternative<const Mesh*>(v) ? io::ViewRole::surface : io::ViewRole::curve;
}

}  // namespace selfsim::interp
