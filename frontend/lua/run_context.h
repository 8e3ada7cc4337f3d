// The state of one `selfsim run`, shared by the sandbox and every binding: where outputs go, the --set
// overrides, limits, and the progress/cancellation of the run. Lives in the Lua registry.
#pragma once

#include <atomic>
#include <chrono>
#include <filesystem>
#include <lua.hpp>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "frontend/lua/live_values.h"
#include "frontend/lua/lua_memory.h"
#include "frontend/lua/param_spec.h"
#include "kernels/base/budget.h"
#include "kernels/base/progress.h"
#include "kernels/io/run_results.h"
#include "kernels/io/view/paraview_view.h"

namespace selfsim::interp {

struct PrintReports;  // print_options.cpp

struct RunConfig {
  std::filesystem::path recipe;
  std::filesystem::path out_dir = "out";
  std::map<std::string, std::string> sets;  // --set key=value
  double max_points = default_max_points;   // points all live values of the run may hold together
  double max_memory = 0;                    // bytes the Lua state may hold; 0 = default_max_memory()
  double timeout = 0;                       // seconds, 0 = none
  long long seed = 0;                       // math.random seed, in [0, 2^63)
  int threads = 0;                          // worker threads for parallel kernels, 0 = all cores
  int jobs = 0;                             // a sweep's runs at a time, 0 = one per core
  bool quiet = false;
  bool view = true;                   // write view.py, a ParaView view of the run's VTK outputs
  std::filesystem::path view_folder;  // the folder view.py names, when not out_dir (--view-folder, for --watch)
  bool watch = false;                 // --watch: run again whenever the recipe or a module changes
  // `selfsim params`: the recipe runs only to collect its param() declarations. Kernels are cancelled at
  // their first check and save() writes nothing, so the heavy part never runs.
  bool params_only = false;
};

// Set by the SIGINT handler; checked by the Lua hook and by every kernel's Progress.
extern std::atomic<bool> interrupted;

// The default --max-memory: a quarter of this machine's memory (6 GiB on 24 GiB), at least 256 MiB.
double default_max_memory();

class RunContext : public Progress {
 public:
  explicit RunContext(RunConfig c);

  const RunConfig config;
  std::filesystem::path scripts_dir;               // the DSL's own library (require "selfsim.curves")
  std::set<std::string> used_params;               // --set keys that param() read
  std::vector<ParamSpec> params;                   // the parameters declared, in order (param_spec.h)
  std::map<std::string, std::size_t> param_index;  // their places in params, by name
  std::string recipe_sha256;                       // of the recipe's bytes, as loaded (run_recipe)
  double held_points = 0;                          // points held by live values (curves), against --max-points
  bool ended = false;                              // the recipe has returned or failed: nothing more may be written
  std::atomic<bool> reported{false};               // the run's error line is printed: the watchdog adds none
  LuaMemory memory;                                // the Lua state's allocator and its --max-memory limit
  LiveValues values;                               // the C++ values the recipe's Lua values stand for
  std::string pending_warning;                     // a warning Lua is still sending in pieces
  // The results the recipe gave (result(name, value), bind_result.cpp), in order, and where each was given.
  std::vector<io::RunResult> results;
  std::map<std::string, std::string> result_where;
  // The files save() has written in this run (bind_io.cpp): by their name inside the output folder, made
  // lexically normal, the name as written and the recipe location ("dragon.lua:3: ") that wrote it; and
  // by their identity (device, inode), the normal name, for names that differ but open the same file.
  std::map<std::string, std::pair<std::string, std::string>> saved;
  std::map<std::pair<unsigned long long, unsigned long long>, std::string> saved_files;
  // The VTK files and series written, in order, for the run's ParaView view (paraview_view.h).
  std::vector<io::ViewDataset> view_datasets;
  // The print checks already made of values still alive (print_options.cpp): a solid's warning, solid.check
  // and save's summary measure it once.
  std::shared_ptr<PrintReports> print_reports;

  // What the run's values may still make: --max-points less what live values hold.
  PointBudget budget() const { return {config.max_points, held_points}; }

  // Progress: a bar on stderr when it is a terminal and the task runs over a second.
  void start(const char* what) override;
  void rename(const char* what) override { task_ = what; }
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
