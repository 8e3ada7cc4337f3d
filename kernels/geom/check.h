// The range and finiteness checks that bindings and kernels share, so that one request gets one message
// wherever it is checked ("level must be an integer in [0, 256], got 300"). The size check is
// check_budget in budget.h.
#pragma once

#include <cmath>
#include <string>

#include "kernels/geom/error.h"

namespace selfsim {

// "[lo, hi]" for messages.
inline std::string range_text(long long lo, long long hi) {
  return "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
}

// Throws Error "<what> must be an integer in [lo, hi], got v" unless lo <= v <= hi.
inline long long check_range(long long v, long long lo, long long hi, const std::string& what) {
  if (v < lo || v > hi)
    throw Error(what + " must be an integer in " + range_text(lo, hi) + ", got " + std::to_string(v));
  return v;
}

// Throws Error "<what> must be a finite number" unless v is finite.
inline double check_finite(double v, const std::string& what) {
  if (!std::isfinite(v)) throw Error(what + " must be a finite number");
  return v;
}

}  // namespace selfsim
