// `selfsim run RECIPE --watch`: runs the recipe, then again whenever it or a file beside it changes (a
// module it requires, a curve it loads), until Ctrl-C. Each run is a child `selfsim run` writing into a
// staging folder inside the output folder; only a run that succeeds has its files moved into the output
// folder, each by one rename, so ParaView's Reload Files sees either the old file or the new one and a
// failed run leaves the last good files as they were. A change while a run is going stops that run (as
// Ctrl-C would: no partial file) and starts the next.
#include <poll.h>
#include <signal.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>

#include "interpreter/commands.h"
#include "interpreter/file_watcher.h"
#include "interpreter/lua_support.h"
#include "interpreter/spawn_selfsim.h"
#include "interpreter/sweep.h"

namespace selfsim::interp {

namespace {

extern "C" void on_watch_signal(int) { interrupted.store(true); }

const char* const staging_name = ".selfsim-next";

std::string clock_text() {
  const std::time_t now = std::time(nullptr);
  char buf[16];
  std::strftime(buf, sizeof buf, "%H:%M:%S", std::localtime(&now));
  return buf;
}

// The arguments of one run: the user's, writing into the staging folder, view.py naming the output folder.
std::vector<std::string> child_arguments(const RunConfig& c, const std::filesystem::path& staging) {
  SweepRun one;
  one.sets = c.sets;
  std::vector<std::string> a = run_arguments(c, one, staging, c.threads);
  a.insert(a.end() - 1, {"--view-folder", std::filesystem::absolute(c.out_dir).lexically_normal().string()});
  return a;
}

// Moves every file of the staging folder to the same place in the output folder, deepest first (a series'
// steps before the series file that names them). Returns the names moved.
std::vector<std::string> publish(const std::filesystem::path& staging, const std::filesystem::path& out) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(staging))
    if (entry.is_regular_file() && !entry.is_symlink()) files.push_back(entry.path().lexically_relative(staging));
  std::stable_sort(files.begin(), files.end(), [](const auto& a, const auto& b) {
    return std::distance(a.begin(), a.end()) > std::distance(b.begin(), b.end());
  });
  std::vector<std::string> names;
  for (const std::filesystem::path& rel : files) {
    const std::filesystem::path to = out / rel;
    // A link planted on the way would lead the rename out of the output folder.
    for (std::filesystem::path up = to.parent_path(); up != out && !up.empty(); up = up.parent_path())
      if (std::filesystem::is_symlink(up)) throw Error("'" + up.string() + "' is a link; not writing through it");
    std::filesystem::create_directories(to.parent_path());
    std::filesystem::rename(staging / rel, to);
    if (!rel.has_parent_path()) names.push_back(rel.string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

// Stops a run (as Ctrl-C does: it leaves no partial file) and reaps it.
void stop(pid_t pid) {
  ::kill(pid, SIGINT);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
}

}  // namespace

int watch_command(const RunConfig& config) {
  if (!std::filesystem::is_regular_file(config.recipe))
    throw UsageError("cannot open recipe '" + config.recipe.string() + "'");
  const std::filesystem::path out = config.out_dir;
  std::filesystem::create_directories(out);
  const std::filesystem::path staging = out / staging_name;
  const std::string exe = selfsim_executable();
  struct sigaction sa {};
  sa.sa_handler = on_watch_signal;  // no SA_RESTART: poll returns at Ctrl-C
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaction(sig, &sa, nullptr);

  // The recipe's folder, and the folder of the file it links to: an edit there is a change too.
  std::vector<std::filesystem::path> folders{std::filesystem::absolute(config.recipe).parent_path()};
  std::error_code ec;
  const std::filesystem::path real = std::filesystem::canonical(config.recipe, ec).parent_path();
  if (!ec && !std::filesystem::equivalent(real, folders[0], ec)) folders.push_back(real);
  // The runs' own writes must not count as changes: the output folder may not hold the recipe.
  const std::filesystem::path real_out = std::filesystem::canonical(out, ec);
  for (const std::filesystem::path& f : folders) {
    const std::string inside = std::filesystem::canonical(f, ec).string() + "/";
    if ((real_out.string() + "/").size() <= inside.size() && inside.starts_with(real_out.string() + "/"))
      throw UsageError("--watch: the output folder '" + out.string() +
                       "' holds the recipe; its writes would count as changes (choose another -o)");
  }
  const char* scripts = std::getenv("SELFSIM_SCRIPTS");
  folders.emplace_back(scripts ? scripts : SELFSIM_SCRIPTS_DIR);
  FileWatcher watcher(folders, out);
  const std::string recipe = shown_text(config.recipe.string());
  if (!config.quiet)
    std::printf("watching %s and the files beside it; outputs in %s (Ctrl-C to stop)\n", recipe.c_str(),
                shown_text(out.string()).c_str());

  for (;;) {
    std::error_code ec;
    std::filesystem::remove_all(staging, ec);
    const auto started = std::chrono::steady_clock::now();
    const pid_t pid = spawn_selfsim(exe, child_arguments(config, staging), {});
    const int pidfd = static_cast<int>(::syscall(SYS_pidfd_open, pid, 0));
    // Wait for the run to end, a change, or Ctrl-C.
    std::string changed;
    int status = 0;
    bool ended = false;
    while (!ended && changed.empty() && !interrupted.load()) {
      pollfd p[2] = {{watcher.fd(), POLLIN, 0}, {pidfd, POLLIN, 0}};
      ::poll(p, pidfd >= 0 ? 2 : 1, pidfd >= 0 ? -1 : 50);
      if (p[0].revents & POLLIN) changed = watcher.take();
      ended = ::waitpid(pid, &status, WNOHANG) == pid;
    }
    if (pidfd >= 0) ::close(pidfd);
    if (!ended) stop(pid);
    if (interrupted.load()) {
      std::filesystem::remove_all(staging, ec);
      return 130;
    }
    if (!changed.empty()) {
      if (!config.quiet)
        std::printf("[%s] %s changed: run stopped, starting again\n", clock_text().c_str(),
                    shown_text(changed).c_str());
      std::fflush(stdout);
      continue;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    const int code = exit_code(status);
    if (code == 0) {
      const std::vector<std::string> names = publish(staging, out);
      std::string list;
      for (const std::string& n : names) list += (list.empty() ? "" : ", ") + shown_text(n);
      if (!config.quiet)
        std::printf("[%s] ran in %.2f s: wrote %s\n", clock_text().c_str(), seconds,
                    list.empty() ? "nothing" : list.c_str());
    } else {
      std::fprintf(stderr, "[%s] the run failed (exit %d); the last good files stay in %s\n", clock_text().c_str(),
                   code, shown_text(out.string()).c_str());
    }
    std::filesystem::remove_all(staging, ec);
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
