#include "frontend/lua/run_context.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace selfsim::interp {

std::atomic<bool> interrupted{false};

double default_max_memory() {
  const double bytes = static_cast<double>(::sysconf(_SC_PHYS_PAGES)) * static_cast<double>(::sysconf(_SC_PAGESIZE));
  return std::max(bytes / 4, 256.0 * (1 << 20));
}

namespace {
const char* const registry_key = "selfsim.RunContext";
}

RunContext::RunContext(RunConfig c)
    : config(std::move(c)),
      started_(std::chrono::steady_clock::now()),
      task_started_(started_),
      tty_(::isatty(2) == 1) {}

void RunContext::start(const char* what) {
  finish_bar();
  task_ = what;
  task_started_ = std::chrono::steady_clock::now();
  last_percent_ = -1;
}

void RunContext::fraction(double done) {
  if (!tty_ || config.quiet) return;
  const auto elapsed = std::chrono::steady_clock::now() - task_started_;
  if (elapsed < std::chrono::seconds(1)) return;
  const int percent = static_cast<int>(std::clamp(done, 0.0, 1.0) * 100);
  if (percent == last_percent_) return;
  last_percent_ = percent;
  constexpr int width = 30;
  std::string bar(static_cast<std::size_t>(percent * width / 100), '#');
  bar.resize(width, '.');
  std::fprintf(stderr, "\r%-24.24s [%s] %3d%% %5.0f s", task_.c_str(), bar.c_str(), percent,
               std::chrono::duration<double>(elapsed).count());
  std::fflush(stderr);
  bar_drawn_ = true;
}

void RunContext::finish_bar() {
  if (bar_drawn_) std::fprintf(stderr, "\r%*s\r", 70, "");
  bar_drawn_ = false;
}

std::string RunContext::stop_reason() const {
  if (interrupted.load()) return "interrupted";
  if (config.timeout > 0 &&
      std::chrono::steady_clock::now() - started_ > std::chrono::duration<double>(config.timeout)) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", config.timeout);
    if (config.params_only)  // `selfsim params`, or a sweep reading the parameters first
      return std::string("stopped: reading the recipe's parameters took over ") + buf +
             " s (a long Lua loop before its first heavy step, or in a finalizer?)";
    return std::string("stopped: --timeout of ") + buf + " s reached";
  }
  return {};
}

bool RunContext::cancelled() { return config.params_only || !stop_reason().empty(); }

RunContext& RunContext::of(lua_State* L) {
  lua_getfield(L, LUA_REGISTRYINDEX, registry_key);
  auto* c = static_cast<RunContext*>(lua_touserdata(L, -1));
  lua_pop(L, 1);
  return *c;
}

void RunContext::install(lua_State* L) {
  lua_pushlightuserdata(L, this);
  lua_setfield(L, LUA_REGISTRYINDEX, registry_key);
}

}  // namespace selfsim::interp
