#include "frontend/process/watchdog.h"

#include <unistd.h>

#include <cstdlib>

#include "frontend/lua/lua_support.h"
#include "kernels/io/output_file.h"

namespace selfsim::interp {

Watchdog::Watchdog(const RunContext& run, std::string recipe)
    : run_(run), recipe_(shown_text(recipe, 500)), thread_([this] { watch(); }) {}

Watchdog::~Watchdog() {
  {
    std::lock_guard lock(mutex_);
    done_ = true;
  }
  wake_.notify_one();
  thread_.join();
}

void Watchdog::watch() {
  std::unique_lock lock(mutex_);
  std::chrono::steady_clock::time_point stop_seen{};
  bool seen = false;
  while (!wake_.wait_for(lock, std::chrono::milliseconds(20), [this] { return done_; })) {
    const std::string reason = run_.stop_reason();
    if (reason.empty()) continue;
    const auto now = std::chrono::steady_clock::now();
    if (!seen) {
      seen = true;
      stop_seen = now;
      continue;
    }
    if (now - stop_seen < grace) continue;
    // The run did not stop by itself: end it here. Nothing is unwound, so only what is safe without the
    // main thread's cooperation is done: one line on stderr, named temporaries removed, exit.
    if (!run_.reported.load()) {
      const std::string line = std::string(::isatty(2) ? "\r\x1b[K" : "") + recipe_ + ": " + reason + "\n";
      [[maybe_unused]] const auto written = ::write(2, line.data(), line.size());
    }
    io::remove_temporaries();
    std::_Exit(interrupted.load() ? 130 : 1);
  }
}

}  // namespace selfsim::interp
