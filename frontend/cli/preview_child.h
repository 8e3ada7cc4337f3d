// Previews drawn as a run is made: by a child `selfsim preview` process (preview_command.cpp) under the run's
// --timeout and --max-memory, so a huge mesh neither blocks the studio's page loop nor takes the studio or a
// sweep down, and a stop (a new run, Ctrl-C, SIGTERM, the parent's death) ends it leaving no partial file.
// The PNGs go through the confined writer (output_file.h) below `root`.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "frontend/lua/run_context.h"

namespace selfsim::interp {

class PreviewChild {
 public:
  // Starts drawing files[i] as root/names[i] (names relative to root, folders made inside it), with the
  // --max-memory of `limits` (0: the default, as for a run) and its --timeout once per file (0: none): the
  // child's timer cannot end one preview and go on, so k previews get the time k of --timeout each would,
  // and every preview that fits the run's --timeout is drawn. Throws Error.
  PreviewChild(const RunConfig& limits, const std::filesystem::path& root, const std::vector<std::string>& files,
               const std::vector<std::string>& names);
  ~PreviewChild();  // stop()
  PreviewChild(const PreviewChild&) = delete;
  PreviewChild& operator=(const PreviewChild&) = delete;

  // Readable when the child has ended (poll it beside other descriptors); -1 when none runs.
  int fd() const { return pidfd_; }
  // When the child has ended: true, with its exit code. False while it goes on.
  bool finished(int& code);
  // Waits for the end; a Ctrl-C meanwhile (interrupted) stops the child. Returns its exit code.
  int wait();
  // Ends the child (SIGTERM: its PNGs are whole or absent) and waits for it.
  void stop();

 private:
  void reaped();
  pid_t pid_ = -1;
  int pidfd_ = -1;
};

// Many previews (a 10,000-run sweep, a run that saved thousands of files) drawn by one child after another,
// in batches of at most 64 previews and 256 KiB of arguments: one command line for all of them would pass
// the kernel's limit on arguments (about 2 MB with the environment), and the child could not start. A
// batch that cannot start is a warning and is skipped (its PNGs are missing: the caller says "no preview").
class PreviewBatches {
 public:
  PreviewBatches(const RunConfig& limits, const std::filesystem::path& root, const std::vector<std::string>& files,
                 const std::vector<std::string>& names);
  // The running batch's descriptor (poll it: readable when that batch ended); -1 when none runs.
  int fd() const { return child_ ? child_->fd() : -1; }
  // Starts the next batch when the running one ended; true once all have ended.
  bool finished();
  // Draws them all, one batch after another. Returns false when stopped by Ctrl-C or SIGTERM (interrupted).
  bool wait();
  // Whether any batch failed to start or ended badly (some previews are missing).
  bool failed() const { return failed_; }

 private:
  void start_next();
  RunConfig limits_;
  std::filesystem::path root_;
  std::vector<std::string> files_, names_;
  std::size_t next_ = 0;
  std::unique_ptr<PreviewChild> child_;  // the running batch; its destructor stops it
  bool failed_ = false;
};

}  // namespace selfsim::interp
