// One recipe run at a time for `run --watch` and the studio: each run is a child `selfsim run` writing into
// a staging folder inside the output folder; only a run that succeeds has its files moved into the output
// folder, each by one rename, so a viewer reloading sees the old file or the new one and a failed run
// leaves the last good files as they were. Starting a run stops the one going (as Ctrl-C would: it leaves
// no partial file).
#pragma once

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "frontend/lua/run_context.h"

namespace selfsim::interp {

struct LiveResult {
  int code = 0;                    // the run's exit code
  double seconds = 0;              // from its start to its end
  std::vector<std::string> files;  // the files it wrote into the output folder's top level, sorted
  std::string log;                 // its messages, when they are captured (the error line first)
};

class LiveRun {
 public:
  // Runs `base` (recipe, output folder, limits). With `capture`, a run's messages go to a log read back
  // into LiveResult::log; else to this process's stdout and stderr.
  LiveRun(RunConfig base, bool capture);
  ~LiveRun();
  LiveRun(const LiveRun&) = delete;
  LiveRun& operator=(const LiveRun&) = delete;

  // Stops a run still going and starts one with these --set values (plain values, not sweep syntax).
  void start(const std::map<std::string, std::string>& sets);
  // Stops a run still going.
  void stop();
  bool running() const { return pid_ > 0; }
  // Readable when the run has ended (poll it beside other descriptors); -1 when none runs.
  int fd() const { return pidfd_; }
  // When the run has ended: its files published (on success) and its result. False while it goes on.
  bool finished(LiveResult& result);

 private:
  RunConfig base_;
  bool capture_;
  std::filesystem::path staging_, log_;
  std::string exe_;
  pid_t pid_ = -1;
  int pidfd_ = -1, lock_ = -1;
  std::chrono::steady_clock::time_point started_;
};

// The folders whose changes should start a run again: the recipe's, the one it links to, and the DSL's
// scripts. Throws UsageError when the output folder holds the recipe (its runs' writes would count as
// changes); `who` names the command in that message.
std::vector<std::filesystem::path> recipe_folders(const RunConfig& config, const std::string& who);

}  // namespace selfsim::interp
