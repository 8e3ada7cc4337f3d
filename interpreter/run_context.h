// The state of one `selfsim run`, shared by the sandbox and every binding: where outputs go, the --set
// overrides, limits, and the progress/cancellation of the run. Lives in the Lua registry.
#pragma once

#include <lua.hpp>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "kernels/geom/progress.h"

namespace selfsim::interp {

struct RunConfig {
  std::filesystem::path recipe;
  std::filesystem::path out_dir = "out";
  std::map<std::string, std::string> sets;  // --set key=value
  double max_points = 1 << 28;              // 268M points: a few GiB, well inside this 24 GiB machine
  double timeout = 0;                       // seconds, 0 = none
  long long seed = 0;                       // math.random seed
  bool quiet = false;
};

// Set by the SIGINT handler; checked by the Lua hook and by every kernel's Progress.
extern std::atomic<bool> interrupted;

class RunContext : public Progress {
 public:
  explicit RunContext(RunConfig c);

  const RunConfig config;
  std::filesystem::path scripts_dir;  // the DSL's own library (require "selfsim.curves")
  std::set<std::string> used_params;  // --set keys that param() read
  std::vector<std::string> saved;     // files written, for the summary

  // Progress: a bar on stderr when it is a terminal and the task runs over a second.
  void start(const char* what) override;
  void fraction(double done) override;
  bool cancelled() override;
  // Why the run is being stopped ("--timeout of 2 s reached", "interrupted"), or empty.
  std::string stop_reason() const;
  // Clears the progress bar line, if one was drawn.
  void finish_bar();

  static RunContext& of(lua_State* L);
  void install(lua_State* L);

 private:
  std::chrono::steady_clock::time_point started_, task_started_;
  std::string task_;
  bool bar_drawn_ = false, tty_ = false;
  int last_percent_ = -1;
};

}  // namespace selfsim::interp
