// Ends the run when a stop (--timeout, Ctrl-C, SIGTERM) is not honoured in time. Lua's hook cannot reach a
// finalizer (hooks are off there, also while the state closes) or a long C call (string.rep of gigabytes, a
// backtracking string.find); there the cooperative stop never comes, and after a grace period the watchdog
// prints the stop message, removes named temporaries and exits the process itself.
#pragma once

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

#include "frontend/lua/run_context.h"

namespace selfsim::interp {

class Watchdog {
 public:
  // Watches `run`; `recipe` names the recipe in the message.
  Watchdog(const RunContext& run, std::string recipe);
  ~Watchdog();  // stops watching
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;

  // How long a cooperative stop may take before the watchdog ends the process.
  static constexpr std::chrono::milliseconds grace{1000};

 private:
  void watch();

  const RunContext& run_;
  const std::string recipe_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false;
  std::thread thread_;
};

}  // namespace selfsim::interp
