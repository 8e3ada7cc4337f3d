// load("name.ext"): a mesh or curve from a file in the recipe's own folder (a region, a start surface, a
// curve drawn elsewhere). Confined like require: a relative name without '..', and no symbolic link
// leading out of the folder. The file is read as `selfsim info` reads it (sizes checked before reading,
// the third-party reader in a limited child process), then counted against --max-points.
#include <cctype>
#include <filesystem>

#include "interpreter/bindings.h"
#include "interpreter/folder_check.h"
#include "interpreter/lua_support.h"
#include "interpreter/options_reader.h"
#include "interpreter/run_context.h"
#include "interpreter/value_types.h"
#include "kernels/io/dataset_values.h"
#include "kernels/io/read.h"

namespace selfsim::interp {

namespace {

const char* const loadable[] = {".vtp", ".vtu", ".stl", ".obj", ".ply", ".svg"};

// The file `name` names inside the recipe's folder; throws Error for a name that could leave it.
std::filesystem::path confined(const RunContext& run, const std::string& name) {
  const std::filesystem::path rel(name);
  if (name.empty() || rel.is_absolute())
    throw Error("'" + shown_text(name) + "' must be a file name relative to the recipe's folder");
  for (const auto& part : rel)
    if (part == "..") throw Error("'" + shown_text(name) + "' leads outside the recipe's folder ('..' is not allowed)");
  std::string ext = rel.extension().string();
  for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));  // x.STL too
  if (std::find(std::begin(loadable), std::end(loadable), ext) == std::end(loadable))
    throw Error("cannot load '" + shown_text(name) +
                "': expected one of: " + quoted_list({std::begin(loadable), std::end(loadable)}));
  const std::filesystem::path folder = run.config.recipe.parent_path();
  const std::filesystem::path file = folder / rel;
  std::error_code ec;
  if (std::filesystem::exists(file, ec) && !resolves_inside(folder, file))
    throw Error("'" + shown_text(name) + "' leads outside the recipe's folder through a symbolic link");
  return file;
}

int load(lua_State* L) {
  return call_kernel(L, "load", [&] {
    RunContext& run = RunContext::of(L);
    const std::string name = text_value(L, 1, "argument 1 (the file name)");
    if (lua_gettop(L) > 1) throw Error("takes one argument, the file name");
    std::variant<Polyline, Polyline3, Mesh> value = io::dataset_value(io::read_dataset(confined(run, name)));
    std::visit(
        [&](auto& v) {
          check_run_budget(L, budget_size(v), "'" + shown_text(name) + "'");
          push_geometry(L, std::move(v));
        },
        value);
    return 1;
  });
}

}  // namespace

void open_load(lua_State* L) { lua_register(L, "load", load); }

}  // namespace selfsim::interp
