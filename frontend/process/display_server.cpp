#include "frontend/process/display_server.h"

#include <dlfcn.h>
#include <fcntl.h>
#include <poll.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <thread>

#include "kernels/base/error.h"

namespace selfsim::interp {

namespace {

// The Xvfb to stop from a signal handler (only async-signal-safe calls there: kill, _exit).
volatile pid_t running_xvfb = -1;

extern "C" void stop_and_exit(int) {
  if (running_xvfb > 0) ::kill(running_xvfb, SIGTERM);
  ::_exit(130);
}

// Xvfb on $PATH, or empty.
std::string find_xvfb() {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/local/bin:/usr/bin:/bin";
  std::size_t begin = 0;
  while (begin <= dirs.size()) {
    std::size_t end = dirs.find(':', begin);
    if (end == std::string::npos) end = dirs.size();
    const std::string dir = end > begin ? dirs.substr(begin, end - begin) : ".";
    const std::string candidate = dir + "/Xvfb";
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
    begin = end + 1;
  }
  return {};
}

// The last non-empty line Xvfb wrote to its stderr (a memfd), for a message about why it failed.
std::string last_line(int fd) {
  std::string text;
  char buffer[4096];
  ::lseek(fd, 0, SEEK_SET);
  for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) > 0;) text.append(buffer, static_cast<std::size_t>(n));
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' ')) text.pop_back();
  std::string line = text.substr(text.find_last_of('\n') == std::string::npos ? 0 : text.find_last_of('\n') + 1);
  for (char& c : line)
    if (static_cast<unsigned char>(c) < 32) c = '?';
  return line.substr(0, 300);
}

void stop(pid_t pid) {
  ::kill(pid, SIGTERM);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  int status = 0;
  while (std::chrono::steady_clock::now() < deadline) {
    const pid_t r = ::waitpid(pid, &status, WNOHANG);
    if (r == pid || (r < 0 && errno != EINTR)) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ::kill(pid, SIGKILL);
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
}

}  // namespace

bool display_reachable() {
  const char* display = std::getenv("DISPLAY");
  if (display == nullptr || *display == '\0') return false;
  // Xlib through dlopen: VTK loads it anyway, and the interpreter needs no X headers or link flags.
  void* x11 = ::dlopen("libX11.so.6", RTLD_NOW | RTLD_LOCAL);
  if (x11 == nullptr) return false;
  using Open = void* (*)(const char*);
  using Close = int (*)(void*);
  const auto open = reinterpret_cast<Open>(::dlsym(x11, "XOpenDisplay"));
  const auto close = reinterpret_cast<Close>(::dlsym(x11, "XCloseDisplay"));
  bool ok = false;
  if (open && close)
    if (void* d = open(nullptr)) {
      close(d);
      ok = true;
    }
  // libX11 stays loaded: unloading it under VTK, which links it, would gain nothing.
  return ok;
}

DisplayServer::DisplayServer() {
  if (display_reachable()) return;
  const std::string xvfb = find_xvfb();
  if (xvfb.empty()) throw Error("no X display and no Xvfb to start one; install it: apt-get install xvfb");
  int ready[2];
  if (::pipe2(ready, O_CLOEXEC) != 0) throw Error(std::string("cannot start Xvfb: ") + std::strerror(errno));
  const int log = ::memfd_create("xvfb-log", MFD_CLOEXEC);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, stop_and_exit);
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid == 0) {
    // The child: dies with selfsim, in its own process group (Ctrl-C is selfsim's to handle), quiet.
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (::getppid() != parent) ::_exit(127);
    ::setpgid(0, 0);
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, SIG_DFL);
    // The X server's memory is not the preview's: the soft --max-memory limit (preview_command.cpp) is lifted.
    if (rlimit data{}; ::getrlimit(RLIMIT_DATA, &data) == 0) {
      data.rlim_cur = data.rlim_max;
      ::setrlimit(RLIMIT_DATA, &data);
    }
    const int null = ::open("/dev/null", O_RDWR);
    ::dup2(null, 0);
    ::dup2(null, 1);
    ::dup2(log >= 0 ? log : null, 2);
    ::fcntl(ready[1], F_SETFD, 0);  // -displayfd must survive exec
    const std::string fd = std::to_string(ready[1]);
    const char* argv[] = {xvfb.c_str(),   "-displayfd", fd.c_str(), "-screen", "0",
                          "1280x1024x24", "-nolisten",  "tcp",      nullptr};
    ::execv(xvfb.c_str(), const_cast<char* const*>(argv));
    ::_exit(127);
  }
  ::close(ready[1]);
  if (pid < 0) {
    const int code = errno;
    ::close(ready[0]);
    if (log >= 0) ::close(log);
    throw Error(std::string("cannot start Xvfb: ") + std::strerror(code));
  }
  xvfb_ = pid;
  running_xvfb = pid;
  // Xvfb writes its display number and a newline to the pipe once it accepts connections.
  std::string number;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  bool ended = false;
  while (number.empty() || number.back() != '\n') {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()).count();
    if (left <= 0) break;
    pollfd p{ready[0], POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(left)) <= 0) continue;
    char c = 0;
    const ssize_t n = ::read(ready[0], &c, 1);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      ended = true;
      break;
    }
    number += c;
  }
  ::close(ready[0]);
  const bool ok = !number.empty() && number.back() == '\n' && number.size() > 1 &&
                  number.find_first_not_of("0123456789\n") == std::string::npos;
  if (!ok) {
    const std::string why = log >= 0 ? last_line(log) : std::string();
    if (log >= 0) ::close(log);
    stop(pid);
    running_xvfb = -1;
    xvfb_ = -1;
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, SIG_DFL);
    throw Error("no X display, and " + xvfb + (ended ? " exited" : " did not start within 20 seconds") +
                (why.empty() ? std::string() : ": " + why));
  }
  if (log >= 0) ::close(log);
  number.pop_back();
  started_ = ":" + number;
  ::setenv("DISPLAY", started_.c_str(), 1);
}

DisplayServer::~DisplayServer() {
  if (xvfb_ <= 0) return;
  running_xvfb = -1;
  stop(xvfb_);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, SIG_DFL);
}

}  // namespace selfsim::interp
