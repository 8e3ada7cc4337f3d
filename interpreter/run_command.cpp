// `selfsim run RECIPE.lua`: runs a recipe in the sandbox and reports its outputs or its one-line error.
#include <csignal>
#include <cstdio>
#include <filesystem>

#include "interpreter/bindings.h"
#include "interpreter/commands.h"
#include "interpreter/sandbox.h"

namespace selfsim::interp {

namespace {

extern "C" void on_interrupt(int) { interrupted.store(true); }

std::filesystem::path find_scripts_dir() {
  if (const char* env = std::getenv("SELFSIM_SCRIPTS")) return env;
  return SELFSIM_SCRIPTS_DIR;
}

}  // namespace

int run_command(const RunConfig& config) {
  if (!std::filesystem::is_regular_file(config.recipe))
    throw UsageError("cannot open recipe '" + config.recipe.string() + "'");
  RunContext run(config);
  run.scripts_dir = find_scripts_dir();
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, on_interrupt);  // stop cleanly: no partial files

  lua_State* L = new_sandbox(run);
  if (L == nullptr) {
    std::fprintf(stderr, "selfsim: cannot create a Lua state (out of memory)\n");
    return 1;
  }
  open_all(L);
  int status = luaL_loadfilex(L, config.recipe.c_str(), "t");
  if (status == LUA_OK) status = lua_pcall(L, 0, 0, 0);
  run.finish_bar();
  int code = 0;
  if (status != LUA_OK) {
    const char* message = lua_tostring(L, -1);
    std::fprintf(stderr, "%s\n", message ? message : "error object is not a string");
    code = interrupted.load() ? 130 : 1;
  } else {
    for (const auto& [key, value] : config.sets)
      if (!run.used_params.contains(key))
        std::fprintf(stderr, "selfsim: warning: --set %s=%s was not read by any param() in the recipe\n", key.c_str(), value.c_str());
    if (!config.quiet)
      for (const auto& s : run.saved) std::printf("wrote %s\n", s.c_str());
  }
  lua_close(L);
  return code;
}

}  // namespace selfsim::interp
