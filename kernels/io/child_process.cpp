#include "kernels/io/child_process.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <thread>

#include "kernels/io/regular_file.h"

#if defined(__SANITIZE_ADDRESS__)
#define SELFSIM_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SELFSIM_ASAN 1
#endif
#endif

namespace selfsim::io {

namespace {

void write_all(int fd, const char* data, std::size_t n) {
  std::size_t done = 0;
  while (done < n) {
    const ssize_t r = ::write(fd, data + done, n - done);
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) throw Error("cannot write to the parent process: " + error_text(errno));
    done += static_cast<std::size_t>(r);
  }
}

}  // namespace

void PipeOut::write(const void* data, std::size_t n) {
  constexpr std::size_t buffered = std::size_t{1} << 16;
  if (n >= buffered) {  // large blocks go straight through
    flush();
    write_all(fd_, static_cast<const char*>(data), n);
    return;
  }
  buffer_.append(static_cast<const char*>(data), n);
  if (buffer_.size() >= buffered) flush();
}

void PipeOut::flush() {
  write_all(fd_, buffer_.data(), buffer_.size());
  buffer_.clear();
}

void PipeIn::wait_readable() {
  for (;;) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline_ - std::chrono::steady_clock::now()).count();
    if (left <= 0) throw ChildTimeout();
    pollfd p{fd_, POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left, 1000)));
    if (ready < 0 && errno != EINTR) throw Error("cannot read from the child process: " + error_text(errno));
    if (ready > 0) return;
  }
}

std::size_t PipeIn::fill() {
  for (;;) {
    wait_readable();
    const ssize_t r = ::read(fd_, buffer_, sizeof buffer_);
    if (r < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (r < 0) throw Error("cannot read from the child process: " + error_text(errno));
    begin_ = 0;
    end_ = static_cast<std::size_t>(r);
    return end_;
  }
}

void PipeIn::read(void* data, std::size_t n) {
  char* out = static_cast<char*>(data);
  while (n > 0) {
    if (begin_ == end_ && n >= sizeof buffer_) {  // large blocks straight into place
      wait_readable();
      const ssize_t r = ::read(fd_, out, n);
      if (r < 0 && (errno == EINTR || errno == EAGAIN)) continue;
      if (r < 0) throw Error("cannot read from the child process: " + error_text(errno));
      if (r == 0) throw ChildEnded();
      out += r;
      n -= static_cast<std::size_t>(r);
      continue;
    }
    if (begin_ == end_ && fill() == 0) throw ChildEnded();
    const std::size_t k = std::min(n, end_ - begin_);
    std::memcpy(out, buffer_ + begin_, k);
    begin_ += k;
    out += k;
    n -= k;
  }
}

bool PipeIn::at_end() { return begin_ == end_ && fill() == 0; }

namespace {

// Address space already mapped by this process (the child inherits it all): the child's limit is this plus
// its allowance. 0 when /proc cannot tell.
std::uint64_t mapped_bytes() {
  std::FILE* f = std::fopen("/proc/self/statm", "r");
  if (!f) return 0;
  unsigned long long pages = 0;
  const int got = std::fscanf(f, "%llu", &pages);
  std::fclose(f);
  return got == 1 ? pages * static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE)) : 0;
}

// In the child, before the work: default signal handling, no terminal output, no core file, limits.
void prepare_child(const ChildLimits& limits, std::uint64_t mapped, pid_t parent) {
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // the child never outlives its parent
  if (::getppid() != parent) ::_exit(5);
  for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGALRM}) std::signal(sig, SIG_DFL);
  sigset_t none;
  sigemptyset(&none);
  ::sigprocmask(SIG_SETMASK, &none, nullptr);
  const int null = ::open("/dev/null", O_RDWR | O_CLOEXEC);
  if (null >= 0)
    for (int fd : {0, 1, 2}) ::dup2(null, fd);
  rlimit no_core{0, 0};
  ::setrlimit(RLIMIT_CORE, &no_core);
#ifndef SELFSIM_ASAN  // AddressSanitizer reserves terabytes of shadow address space: no RLIMIT_AS under it
  if (limits.memory_bytes > 0 && mapped > 0) {
    rlimit as{};
    as.rlim_cur = as.rlim_max = static_cast<rlim_t>(mapped + limits.memory_bytes);
    ::setrlimit(RLIMIT_AS, &as);
  }
#else
  (void)mapped;
#endif
  // A backstop: the parent kills the child itself at the deadline.
  ::alarm(static_cast<unsigned>(std::ceil(limits.seconds)) + 10);
}

// Waits for the child until the deadline, then kills it. Returns false when it had to be killed.
bool wait_child(pid_t pid, std::chrono::steady_clock::time_point deadline, int& status) {
  for (;;) {
    const pid_t r = ::waitpid(pid, &status, WNOHANG);
    if (r == pid) return true;
    if (r < 0 && errno != EINTR) return true;  // not ours to wait for any more
    if (std::chrono::steady_clock::now() >= deadline) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ::kill(pid, SIGKILL);
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return false;
}

std::string seconds_text(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f", s);
  return buf;
}

}  // namespace

void run_in_child(const ChildLimits& limits, const std::function<int(PipeOut&)>& child,
                  const std::function<void(PipeIn&)>& parent) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw Error("cannot start " + limits.what + ": " + error_text(errno));
  ::fcntl(fds[0], F_SETPIPE_SZ, 1 << 20);  // fewer round trips for large results; the default still works
  const std::uint64_t mapped = mapped_bytes();
  const pid_t parent_pid = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int code = errno;
    ::close(fds[0]);
    ::close(fds[1]);
    throw Error("cannot start " + limits.what + ": " + error_text(code));
  }
  if (pid == 0) {
    ::close(fds[0]);
    int code = 4;
    try {
      prepare_child(limits, mapped, parent_pid);
      PipeOut out(fds[1]);
      code = child(out);
      out.flush();
    } catch (const std::bad_alloc&) {
      code = 3;
    } catch (...) {
      code = 4;
    }
    ::_exit(code);  // no destructors, no atexit handlers, no stdio flush of the parent's buffers
  }
  ::close(fds[1]);
  const auto deadline =
      std::chrono::steady_clock::now() +
      std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(limits.seconds));
  PipeIn in(fds[0], deadline);
  std::exception_ptr failure;
  bool timed_out = false, ended_early = false;
  try {
    parent(in);
    if (!in.at_end()) failure = std::make_exception_ptr(Error(limits.what + " sent more than was expected"));
  } catch (const ChildTimeout&) {
    timed_out = true;
  } catch (const ChildEnded&) {
    ended_early = true;
  } catch (...) {
    failure = std::current_exception();
  }
  ::close(fds[0]);
  int status = 0;
  if (timed_out || failure) {
    ::kill(pid, SIGKILL);
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
  } else if (!wait_child(pid, deadline, status)) {
    timed_out = true;
  }
  if (timed_out) throw Error(limits.what + " did not finish within " + seconds_text(limits.seconds) + " seconds");
  if (failure) std::rethrow_exception(failure);
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    if (sig == SIGKILL) throw Error(limits.what + " was killed (out of memory?)");
    const char* name = ::strsignal(sig);
    throw Error(limits.what + " crashed (" + (name ? std::string(name) : "signal " + std::to_string(sig)) + ")");
  }
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (code == 3) throw Error(limits.what + " ran out of memory");
  if (code != 0) throw Error(limits.what + " failed (exit status " + std::to_string(code) + ")");
  if (ended_early) throw Error(limits.what + " ended its answer early");
}

}  // namespace selfsim::io
