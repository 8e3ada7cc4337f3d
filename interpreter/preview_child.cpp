#include "interpreter/preview_child.h"

#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>

#include "interpreter/commands.h"
#include "interpreter/spawn_selfsim.h"
#include "interpreter/sweep.h"

namespace selfsim::interp {

PreviewChild::PreviewChild(const RunConfig& limits, const std::filesystem::path& root,
                           const std::vector<std::string>& files, const std::vector<std::string>& names) {
  std::vector<std::string> args{"preview", "-q", "-o", root.string()};
  if (limits.timeout > 0) {
    char seconds[64];
    std::snprintf(seconds, sizeof seconds, "%.17g", limits.timeout);
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

}  // namespace selfsim::interp
