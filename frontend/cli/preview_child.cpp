#include "frontend/cli/preview_child.h"

#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>

#include "frontend/cli/commands.h"
#include "frontend/process/spawn_selfsim.h"

namespace selfsim::interp {

PreviewChild::PreviewChild(const RunConfig& limits, const std::filesystem::path& root,
                           const std::vector<std::string>& files, const std::vector<std::string>& names) {
  std::vector<std::string> args{"preview", "-q", "-o", root.string()};
  if (limits.timeout > 0) {
    char seconds[64];
    std::snprintf(seconds, sizeof seconds, "%.17g", limits.timeout * static_cast<double>(files.size()));
    args.insert(args.end(), {"--timeout", seconds});
  }
  const double memory = limits.max_memory > 0 ? limits.max_memory : default_max_memory();
  args.insert(args.end(), {"--max-memory", std::to_string(static_cast<long long>(memory))});
  for (std::size_t i = 0; i < files.size(); ++i) args.insert(args.end(), {"--as", names.at(i), files[i]});
  pid_ = spawn_selfsim(selfsim_executable(), args, {});
  pidfd_ = static_cast<int>(::syscall(SYS_pidfd_open, pid_, 0));
}

PreviewChild::~PreviewChild() { stop(); }

void PreviewChild::reaped() {
  if (pidfd_ >= 0) ::close(pidfd_);
  pid_ = pidfd_ = -1;
}

bool PreviewChild::finished(int& code) {
  if (pid_ <= 0) return false;
  int status = 0;
  if (::waitpid(pid_, &status, WNOHANG) != pid_) return false;
  reaped();
  code = exit_code(status);
  return true;
}

int PreviewChild::wait() {
  if (pid_ <= 0) return 0;
  // A stop signal that came before this wait began has set `interrupted` and will bring no EINTR: so the
  // signals are blocked, the flag read, and the wait is a ppoll that unblocks them only while it sleeps (one
  // pending is delivered at once, ending it with EINTR). No signal can fall between the check and the wait.
  sigset_t stops, before;
  sigemptyset(&stops);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&stops, sig);
  ::pthread_sigmask(SIG_BLOCK, &stops, &before);
  while (!interrupted.load() && pidfd_ >= 0) {
    pollfd p{pidfd_, POLLIN, 0};
    const int r = ::ppoll(&p, 1, nullptr, &before);
    if (r > 0 || (r < 0 && errno != EINTR)) break;  // ended (or no waiting possible: waitpid below)
  }
  ::pthread_sigmask(SIG_SETMASK, &before, nullptr);
  if (interrupted.load()) {  // SIGCONT: a stopped child would hold SIGTERM
    ::kill(pid_, SIGTERM);
    ::kill(pid_, SIGCONT);
  }
  int status = 0;
  // Without a pidfd (an old kernel) this is the wait: a signal now still ends it by EINTR, the flag read after.
  while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR)
    if (interrupted.load()) {
      ::kill(pid_, SIGTERM);
      ::kill(pid_, SIGCONT);
    }
  reaped();
  return exit_code(status);
}

void PreviewChild::stop() {
  if (pid_ <= 0) return;
  ::kill(pid_, SIGTERM);  // Xvfb and the renderer's child end with it; a PNG is whole or not there
  ::kill(pid_, SIGCONT);  // a stopped child (Ctrl-Z, a debugger) would hold SIGTERM, and this wait, forever
  int status = 0;
  while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  reaped();
}

namespace {

constexpr std::size_t batch_previews = 64, batch_bytes = std::size_t{256} << 10;

}  // namespace

PreviewBatches::PreviewBatches(const RunConfig& limits, const std::filesystem::path& root,
                               const std::vector<std::string>& files, const std::vector<std::string>& names)
    : limits_(limits), root_(root), files_(files), names_(names) {
  start_next();
}

void PreviewBatches::start_next() {
  child_.reset();
  while (next_ < files_.size()) {
    // Each argument counted with its NUL and its pointer; a name is below PATH_MAX, so any one preview fits.
    std::size_t end = next_, bytes = 0;
    while (end < files_.size() && end - next_ < batch_previews) {
      const std::size_t more = 3 * (sizeof(char*) + 1) + 4 + names_[end].size() + files_[end].size();  // --as
      if (end > next_ && bytes + more > batch_bytes) break;
      bytes += more;
      ++end;
    }
    const std::vector<std::string> files(files_.begin() + next_, files_.begin() + end);
    const std::vector<std::string> names(names_.begin() + next_, names_.begin() + end);
    const std::size_t first = next_;
    next_ = end;
    try {
      child_ = std::make_unique<PreviewChild>(limits_, root_, files, names);
      return;
    } catch (const Error& e) {
      std::fprintf(stderr, "selfsim: warning: previews %zu to %zu of %zu not drawn: %s\n", first + 1, end,
                   files_.size(), e.what());
      failed_ = true;
    }
  }
}

bool PreviewBatches::finished() {
  if (!child_) return true;
  if (int code = 0; child_->finished(code)) {
    failed_ = failed_ || code != 0;
    start_next();
  }
  return !child_;
}

bool PreviewBatches::wait() {
  while (child_) {
    failed_ = child_->wait() != 0 || failed_;
    if (interrupted.load()) return false;
    start_next();
  }
  return true;
}

}  // namespace selfsim::interp
