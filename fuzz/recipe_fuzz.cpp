// Fuzz target: recipe text run the way `selfsim run` runs it (frontend/cli/run_command.cpp): a sandbox
// from new_sandbox, every binding from open_all, the input loaded as a text chunk and called with
// lua_pcall. Small limits keep each execution short: --max-points 1e5, --timeout 0.25 s, --max-memory
// 64 MiB (a recipe that builds a huge string gets a Lua memory error instead of taking the fuzzer down).
// `print` is kept but writes nothing.
//
// Findings: crashes, leaks, any C++ exception escaping a binding (the C++ build of Lua turns one into a
// pcall status outside LUA_ERRRUN..LUA_ERRERR, checked here), and any file written outside the output
// folder.
//
// Hangs: `selfsim run` has a watchdog (frontend/process/watchdog.h) that ends the process when a stop is not
// honoured within a grace period, by design the answer to what Lua's hook cannot reach (an endless
// finalizer, a backtracking string.find). The same happens here: an input still running 3 s after it
// started (--timeout 0.25 s, the grace 0.5 s, and room for the sanitizers) ends the process with status 0
// and a "FUZZ-WATCHDOG" line, so libFuzzer's -fork mode starts a new job and these designed-for stops are
// not reported as hangs. Set SELFSIM_FUZZ_NO_WATCHDOG=1 to have libFuzzer's -timeout report them instead.
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <lua.hpp>
#include <string>
#include <thread>

#include "frontend/bindings/bindings.h"
#include "frontend/lua/run_context.h"
#include "frontend/lua/sandbox.h"
#include "fuzz/fuzz_support.h"

namespace {

namespace fs = std::filesystem;
using namespace selfsim;

// print(...) converts its arguments as Lua's does (running __tostring) and writes nothing.
int quiet_print(lua_State* L) {
  for (int i = 1, n = lua_gettop(L); i <= n; ++i) {
    luaL_tolstring(L, i, nullptr);
    lua_pop(L, 1);
  }
  return 0;
}

const fs::path& root() {
  static const fs::path r = [] {
    const fs::path p = fs::temp_directory_path() / ("selfsim-fuzz-recipe-" + std::to_string(::getpid()));
    fs::remove_all(p);
    fs::create_directories(p / "recipe");
    return p;
  }();
  static const struct Remove {
    ~Remove() {
      std::error_code ignored;
      fs::remove_all(r, ignored);
    }
  } remove_at_exit;
  return r;
}

// Nothing but the recipe folder (empty) and the output folder may be in the root after a run.
void check_and_clean(const fs::path& out_dir) {
  for (const auto& entry : fs::directory_iterator(root())) {
    const std::string name = entry.path().filename().string();
    if (name == "recipe") {
      if (!fs::is_empty(entry.path()))
        fuzz::finding("a file was written in the recipe's folder: " +
                      fs::directory_iterator(entry.path())->path().string());
    } else if (entry.path() != out_dir) {
      fuzz::finding("a file was written outside the output folder: " + entry.path().string());
    }
  }
  fs::remove_all(out_dir);
}

using Clock = std::chrono::steady_clock;
std::atomic<Clock::rep> input_started{0};  // 0: no input running
constexpr auto stall = std::chrono::seconds(3);

void watchdog() {
  for (;;) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    const Clock::rep started = input_started.load();
    if (started != 0 && Clock::now() - Clock::time_point(Clock::duration(started)) > stall) {
      std::fprintf(
          stderr,
          "FUZZ-WATCHDOG: the input did not stop within %lld s; selfsim run's watchdog would end the run here\n",
          static_cast<long long>(stall.count()));
      std::fflush(stderr);
      std::_Exit(0);
    }
  }
}

struct InputTimer {
  InputTimer() { input_started.store(Clock::now().time_since_epoch().count()); }
  ~InputTimer() { input_started.store(0); }
};

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  if (!fuzz::env_flag("SELFSIM_FUZZ_NO_WATCHDOG")) std::thread(watchdog).detach();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  interp::RunConfig config;
  config.recipe = root() / "recipe" / "recipe.lua";
  config.out_dir = root() / "out";
  config.sets = {{"level", "2"}, {"scale", "0.5"}, {"name", "x"}, {"flag", "true"}};
  config.max_points = 1e5;
  config.max_memory = 64 << 20;
  config.timeout = 0.25;
  config.quiet = true;
  int status = LUA_OK;
  const InputTimer timer;
  try {
    interp::RunContext run(config);
    run.scripts_dir = SELFSIM_SCRIPTS_DIR;
    lua_State* L = interp::new_sandbox(run);
    if (L == nullptr) fuzz::finding("new_sandbox returned no state");
    interp::open_all(L);
    lua_pushcfunction(L, quiet_print);
    lua_setglobal(L, "print");
    const std::string chunkname = "@" + config.recipe.string();
    status = luaL_loadbufferx(L, reinterpret_cast<const char*>(data), size, chunkname.c_str(), "t");
    if (status == LUA_OK) status = lua_pcall(L, 0, 0, 0);
    run.ended = true;  // as run_command: finalizers still to run at lua_close can no longer write
    if (status != LUA_OK && status != LUA_ERRRUN && status != LUA_ERRMEM && status != LUA_ERRERR &&
        status != LUA_ERRSYNTAX) {
      const char* message = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : "(not a string)";
      fuzz::finding("lua_pcall returned status " + std::to_string(status) +
                    ": a C++ exception escaped a binding; message on the stack: " + message);
    }
    lua_close(L);
  } catch (...) {
    fuzz::unexpected_exception("running the recipe");
  }
  check_and_clean(config.out_dir);
  return 0;
}
