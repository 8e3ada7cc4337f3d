// The cut symbol '%' as a filter over a stream of modules (module_rewrite.cpp). Internal to
// kernels/lsystem.
#pragma once

#include <cstdint>

namespace selfsim::lsystem {

// '%' cuts the rest of its branch (ABOP 1.10): modules written after it are dropped up to the ']' that
// closes the branch it is in.
struct Cut {
  bool active = false;
  int depth = 0;

  // Whether a module of symbol s is kept (and updates the state).
  bool keep(std::uint8_t s) {
    if (!active) {
      if (s != '%') return true;
      active = true;
      depth = 0;
      return false;
    }
    if (s == '[') ++depth;
    if (s == ']' && depth-- == 0) {
      active = false;
      return true;
    }
    return false;
  }
};

}  // namespace selfsim::lsystem
