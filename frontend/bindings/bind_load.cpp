// load("name.ext"): a mesh or curve from a file in the recipe's own folder (a region, a start surface, a
// curve drawn elsewhere). Confined: a relative name without '..', opened without following any symbolic
// link. The file is read as `selfsim info` reads it (sizes checked against the file before reading, VTK in
// a limited child process, selfsim's own strict readers for STL, OBJ and PLY), then counted against
// --max-points.
#include <algorithm>
#include <cctype>
#include <filesystem>

#include "frontend/bindings/bindings.h"
#include "frontend/lua/folder_check.h"
#include "frontend/lua/lua_support.h"
#include "frontend/lua/options_reader.h"
#include "frontend/lua/run_context.h"
#include "frontend/lua/value_types.h"
#include "kernels/base/lower_case.h"
#include "kernels/io/dataset/dataset_values.h"
#include "kernels/io/read.h"
#include "kernels/io/regular_file.h"
#include "kernels/io/vdb/vdb_read.h"

namespace selfsim::interp {

namespace {

const char* const loadable[] = {".vtp", ".vtu", ".stl", ".obj", ".ply", ".svg", ".vdb"};

// Checks `name`: relative, without '..', with a loadable extension.
void check_name(const std::string& name) {
  const std::filesystem::path rel(name);
  if (name.empty() || rel.is_absolute())
    throw Error("'" + shown_text(name) + "' must be a file name relative to the recipe's folder");
  for (const auto& part : rel)
    if (part == "..") throw Error("'" + shown_text(name) + "' leads outside the recipe's folder ('..' is not allowed)");
  const std::string ext = lower_case(rel.extension().string());  // x.STL too
  if (std::find(std::begin(loadable), std::end(loadable), ext) == std::end(loadable))
    throw Error("cannot load '" + shown_text(name) +
                "': expected one of: " + quoted_list({std::begin(loadable), std::end(loadable)}));
}

// Throws Error when `name` is not there: where load looked (the recipe's folder, as the recipe names it,
// never this machine's absolute path) and the likeliest file meant among the loadable ones beside it.
void check_found(const std::filesystem::path& folder, const std::string& name) {
  const std::filesystem::path rel(name);
  std::error_code ec;
  const auto status = std::filesystem::symlink_status(folder / rel, ec);
  if (status.type() != std::filesystem::file_type::not_found) return;  // anything else: FileBeneath decides
  const std::filesystem::path sub = rel.parent_path();
  const std::vector<std::string> files = files_in(folder / sub, {std::begin(loadable), std::end(loadable)});
  std::string near;
  const std::string leaf = rel.filename().string();
  for (const std::string& f : files)  // "Torus.STL" for "torus.stl"
    if (lower_case(f) == lower_case(leaf)) near = f;
  if (near.empty()) near = suggestion(leaf, files);
  const std::string meant = near.empty() ? "" : (sub / near).generic_string();
  throw Error("'" + shown_text(name) + "' not found in the recipe's folder" +
              (meant.empty() ? "" : " (did you mean '" + shown_text(meant) + "'?)"));
}

int load(lua_State* L) {
  return call_kernel(L, "load", [&] {
    const std::string name = text_value(L, 1, "argument 1 (the file name)");
    if (lua_gettop(L) > 1) throw Error("takes one argument, the file name");
    std::variant<Polyline, Polyline3, Mesh> value = load_value(L, name);
    std::visit([&](auto& v) { push_geometry(L, std::move(v)); }, value);
    return 1;
  });
}

}  // namespace

std::variant<Polyline, Polyline3, Mesh> load_value(lua_State* L, const std::string& name, const std::string& grid,
                                                   GridSamples* samples) {
  check_name(name);
  check_found(RunContext::of(L).config.recipe.parent_path(), name);
  // Opened without following any link, and read through that descriptor: the name cannot be swapped
  // for a link to somewhere else between the check and the read.
  const io::FileBeneath file(RunContext::of(L).config.recipe.parent_path(), name);
  const bool vdb = lower_case(std::filesystem::path(name).extension().string()) == ".vdb";
  if (!grid.empty() && !vdb) throw Error("option 'grid' is for .vdb files, not '" + shown_text(name) + "'");
  // A .vdb file: the surface of its level set (or the grid named), meshed by OpenVDB (vdb_read.h), and the
  // level set's voxels for a caller that asks.
  io::Dataset read;
  if (vdb) {
    // Its active tiles (and, for a caller that asks, its voxels) weighed against the run's budget first.
    io::VdbSurface surface = with_budget(L, [&](const PointBudget& budget) {
      return io::read_vdb_surface(file.name(),
                                  {.grid = grid, .shown_as = name, .budget = budget, .samples = samples != nullptr});
    });
    read = std::move(surface.mesh);
    if (samples) {
      check_run_budget(L, static_cast<double>(surface.samples.bytes()) / 16,
                       "the level set of '" + shown_text(name) + "'");
      *samples = std::move(surface.samples);
    }
  } else {
    read = io::read_dataset(file.name(), name);
  }
  std::variant<Polyline, Polyline3, Mesh> value;
  try {
    value = io::dataset_value(read, RunContext::of(L));
  } catch (const BudgetError&) {
    throw;
  } catch (const Cancelled&) {
    throw;
  } catch (const Error& e) {  // what the file holds cannot be a value: say which file, as the readers do
    throw Error("cannot read '" + shown_text(name) + "': " + e.what());
  }
  std::visit([&](auto& v) { check_run_budget(L, budget_size(v), "'" + shown_text(name) + "'"); }, value);
  return value;
}

void open_load(lua_State* L) { lua_register(L, "load", load); }

}  // namespace selfsim::interp
