// Previews drawn as a run is made: by a child `selfsim preview` process (preview_command.cpp) under the run's
// --timeout and --max-memory, so a huge mesh neither blocks the studio's page loop nor takes the studio or a
// sweep down, and a stop (a new run, Ctrl-C, SIGTERM, the parent's death) ends it leaving no partial file.
// The PNGs go through the confined writer (output_file.h) below `root`.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

#include "interpreter/run_context.h"

namespace selfsim::interp {

class PreviewChild {
 public:
  // Starts drawing files[i] as root/names[i] (names relative to root, folders made inside it), with the
  // --timeout and --max-memory of `limits` (0: none / the default, as for a run). Throws Error.
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

}  // namespace selfsim::interp
