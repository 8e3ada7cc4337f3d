// Predicted sizes in error messages: exact digits while a double holds the count exactly (below 2^53),
// else "about 1.6e+60".
#pragma once

#include <cstdio>
#include <string>

namespace selfsim {

inline std::string count_text(double n) {
  if (n < 9007199254740992.0) return std::to_string(static_cast<long long>(n));
  char buf[32];
  std::snprintf(buf, sizeof buf, "about %.2g", n);
  return buf;
}

}  // namespace selfsim
