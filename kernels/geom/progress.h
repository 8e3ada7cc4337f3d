// How long kernels report what fraction is done and learn that they should stop, in the spirit of
// OpenVDB's interrupters. Kernels call step() once per outer chunk of work, never per point.
#pragma once

#include "kernels/geom/error.h"

namespace selfsim {

class Progress {
 public:
  virtual ~Progress() = default;
  // A new task begins; `what` is a short name for display ("dragon level 26").
  virtual void start(const char* /*what*/) {}
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

// For callers that want neither reports nor cancellation (tests, benches).
inline Progress& no_progress() {
  static Progress p;
  return p;
}

}  // namespace selfsim
