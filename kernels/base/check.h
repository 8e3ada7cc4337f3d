// The range and finiteness checks that bindings and kernels share, so that one request gets one message
// wherever it is checked ("level must be an integer in [0, 256], got 300"). The size check is
// check_budget in budget.h.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

#include "kernels/base/error.h"

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

// A number as messages show it: NaN (never "-nan"), inf, or up to 14 significant digits.
inline std::string number_text(double v) {
  if (std::isnan(v)) return "NaN";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.14g", v);
  return buf;
}

// Throws Error "<what> must be a number in [lo, hi], got v" unless lo <= v <= hi (NaN never is).
inline double check_between(double v, double lo, double hi, const std::string& what) {
  if (!(v >= lo && v <= hi))
    throw Error(what + " must be a number in [" + number_text(lo) + ", " + number_text(hi) + "], got " +
                number_text(v));
  return v;
}

// Throws Error "<what> must be a finite number, got NaN" unless v is finite.
inline double check_finite(double v, const std::string& what) {
  if (!std::isfinite(v)) throw Error(what + " must be a finite number, got " + number_text(v));
  return v;
}

}  // namespace selfsim
