// `selfsim run RECIPE --watch`: runs the recipe, then again whenever it or a file beside it changes (a
// module it requires, a curve it loads), until Ctrl-C. The runs are live_run.h's: staged, published only
// when they succeed, and a change while a run is going stops it and starts the next.
#include <poll.h>
#include <signal.h>

#include <cstdio>
#include <ctime>

#include "frontend/cli/commands.h"
#include "frontend/cli/watch/file_watcher.h"
#include "frontend/cli/watch/live_run.h"
#include "frontend/lua/lua_support.h"

namespace selfsim::interp {

namespace {

extern "C" void on_watch_signal(int) { interrupted.store(true); }

std::string clock_text() {
  const std::time_t now = std::time(nullptr);
  char buf[16];
  std::strftime(buf, sizeof buf, "%H:%M:%S", std::localtime(&now));
  return buf;
}

}  // namespace

int watch_command(const RunConfig& config) {
  if (!std::filesystem::is_regular_file(config.recipe))
    throw UsageError("cannot open recipe '" + config.recipe.string() + "'");
  struct sigaction sa {};
  sa.sa_handler = on_watch_signal;  // no SA_RESTART: poll returns at Ctrl-C
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaction(sig, &sa, nullptr);
  FileWatcher watcher(recipe_folders(config, "--watch"), config.out_dir);
  watcher.follow(config.recipe);  // the recipe may become a link (or point elsewhere) while watched
  LiveRun live(config, false);
  const std::string out = shown_text(config.out_dir.string());
  if (!config.quiet)
    std::printf("watching %s and the files beside it; outputs in %s (Ctrl-C to stop)\n",
                shown_text(config.recipe.string()).c_str(), out.c_str());
  for (;;) {
    live.start(config.sets);
    // Wait for the run to end, a change, or Ctrl-C.
    std::string changed;
    LiveResult result;
    bool ended = false;
    while (!ended && changed.empty() && !interrupted.load()) {
      pollfd p[2] = {{watcher.fd(), POLLIN, 0}, {live.fd(), POLLIN, 0}};
      ::poll(p, live.fd() >= 0 ? 2 : 1, live.fd() >= 0 ? -1 : 50);
      if (p[0].revents & POLLIN) changed = watcher.take();
      ended = live.finished(result);
    }
    if (interrupted.load()) return 130;
    if (!changed.empty() && !ended) {
      if (!config.quiet)
        std::printf("[%s] %s changed: run stopped, starting again\n", clock_text().c_str(),
                    shown_text(changed).c_str());
      std::fflush(stdout);
      continue;
    }
    if (result.code == 0) {
      std::string list;
      for (const std::string& n : result.files) list += (list.empty() ? "" : ", ") + shown_text(n);
      if (!config.quiet)
        std::printf("[%s] ran in %.2f s: wrote %s\n", clock_text().c_str(), result.seconds,
                    list.empty() ? "nothing" : list.c_str());
    } else {
      std::fprintf(stderr, "[%s] the run failed (exit %d); the last good files stay in %s\n", clock_text().c_str(),
                   result.code, out.c_str());
    }
    std::fflush(stdout);
    std::fflush(stderr);
    // Wait for the next change.
    while (changed.empty() && !interrupted.load()) changed = watcher.wait(std::chrono::hours(24));
    if (interrupted.load()) return 130;
    if (!config.quiet) std::printf("[%s] %s changed\n", clock_text().c_str(), shown_text(changed).c_str());
    std::fflush(stdout);
  }
}

}  // namespace selfsim::interp
