// Running work that may crash, exhaust memory or hang (a third-party file reader fed a hostile file) in a
// forked child process: its address space and running time are limited, its stdout and stderr go to
// /dev/null, and its result comes back over a pipe. A crash, an allocation failure or a hang in the child
// becomes an Error in the caller instead of taking the caller down.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

#include "kernels/base/error.h"

namespace selfsim::io {

// Thrown by PipeIn: the child closed the pipe before the parent read all it expected / the time ran out.
struct ChildEnded : Error {
  ChildEnded() : Error("the child process ended its answer early") {}
};
struct ChildTimeout : Error {
  ChildTimeout() : Error("the child process ran out of time") {}
};

// The writing end of the result pipe, in the child. Buffered; throws Error when the parent went away.
class PipeOut {
 public:
  explicit PipeOut(int fd) : fd_(fd) {}
  ~PipeOut() = default;
  void write(const void* data, std::size_t n);
  void flush();

 private:
  int fd_;
  std::string buffer_;
};

// The reading end, in the parent: read() waits at most until the deadline.
class PipeIn {
 public:
  PipeIn(int fd, std::chrono::steady_clock::time_point deadline) : fd_(fd), deadline_(deadline) {}
  // Reads exactly n bytes; throws ChildTimeout past the deadline, ChildEnded when the child closed the pipe first.
  void read(void* data, std::size_t n);
  // True when the child closed the pipe with nothing more in it.
  bool at_end();

 private:
  void wait_readable();
  std::size_t fill();
  int fd_;
  std::chrono::steady_clock::time_point deadline_;
  char buffer_[1 << 16];
  std::size_t begin_ = 0, end_ = 0;
};

struct ChildLimits {
  std::string what = "the reader";  // names the child in messages: "the VTK reader crashed (Segmentation fault)"
  std::uint64_t memory_bytes = 0;   // address space the child may add to what it inherits; 0: no limit
  double seconds = 60;              // wall-clock limit; the child is killed after it
};

// Runs child(pipe) in a forked process (its return value is the exit status; exceptions that escape it are
// exit status 3 for std::bad_alloc, 4 otherwise), while parent(pipe) reads the result here. Throws Error
// naming what happened when the child crashed, was killed, ran out of memory or time, or exited with a
// nonzero status; rethrows parent's own exception when the child ended normally.
void run_in_child(const ChildLimits& limits, const std::function<int(PipeOut&)>& child,
                  const std::function<void(PipeIn&)>& parent);

}  // namespace selfsim::io
