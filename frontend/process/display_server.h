// An X display for VTK, which renders through X only on Debian (no OSMesa, no EGL): the user's $DISPLAY
// when it can be connected to, otherwise an Xvfb started for this run (front-end code: kernels know
// nothing of it). The Xvfb is stopped when the DisplayServer ends, on an error, on Ctrl-C (SIGINT, SIGTERM,
// SIGHUP: the handler stops it and exits 130) and, should selfsim be killed outright, by the kernel
// (PR_SET_PDEATHSIG).
#pragma once

#include <sys/types.h>

#include <string>

namespace selfsim::interp {

class DisplayServer {
 public:
  // Throws selfsim::Error with one line: "no X display and no Xvfb to start one; install it: apt-get
  // install xvfb", or why the Xvfb found did not start.
  DisplayServer();
  ~DisplayServer();
  DisplayServer(const DisplayServer&) = delete;
  DisplayServer& operator=(const DisplayServer&) = delete;

  // ":N" of the Xvfb started, empty when the user's display is used.
  const std::string& started() const { return started_; }

 private:
  pid_t xvfb_ = -1;
  std::string started_;
};

// True when $DISPLAY names an X server that accepts a connection now.
bool display_reachable();

}  // namespace selfsim::interp
