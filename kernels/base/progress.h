// How long kernels report what fraction is done and learn that they should stop, in the spirit of
// OpenVDB's interrupters. Kernels call step() once per outer chunk of work, never per point.
// Threads: cancelled() may be called from any thread (implementations make it safe); start() and
// fraction() only from the thread that called the kernel, which alone reports.
#pragma once

#include "kernels/base/error.h"

namespace selfsim {

class Progress {
 public:
  virtual ~Progress() = default;
  // A new task begins; `what` is a short name for display ("dragon level 26").
  virtual void start(const char* /*what*/) {}
  // The same task goes on under another name ("thickening" within "developing surface").
  virtual void rename(const char* /*what*/) {}
  // Fraction done in [0, 1].
  virtual void fraction(double /*done*/) {}
  // True when the run should stop as soon as possible.
  virtual bool cancelled() { return false; }

  // Reports and throws Cancelled if the run should stop.
  void step(double done) {
    fraction(done);
    if (cancelled()) throw Cancelled();
  }
};

// One stage of a kernel with several: reports its own progress [0, 1] as [begin, end] of the parent's;
// the task it starts renames the parent's; cancellation is the parent's.
class ProgressStage : public Progress {
 public:
  ProgressStage(Progress& parent, double begin, double end) : parent_(parent), begin_(begin), end_(end) {}
  void start(const char* what) override { parent_.rename(what); }
  void rename(const char* what) override { parent_.rename(what); }
  void fraction(double done) override { parent_.fraction(begin_ + done * (end_ - begin_)); }
  bool cancelled() override { return parent_.cancelled(); }

 private:
  Progress& parent_;
  double begin_, end_;
};

// For callers that want neither reports nor cancellation (tests, benches).
inline Progress& no_progress() {
  static Progress p;
  return p;
}

}  // namespace selfsim
