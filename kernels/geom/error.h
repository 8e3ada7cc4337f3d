// The one exception type kernels throw for bad input or impossible requests. The message names the option
// or input at fault ("option 'level' must be ..."); the interpreter prefixes the recipe file:line.
#pragma once

#include <stdexcept>
#include <string>

namespace selfsim {

struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Thrown by kernels when Progress::cancelled() became true (Ctrl-C, --timeout).
struct Cancelled : Error {
  Cancelled() : Error("cancelled") {}
};

}  // namespace selfsim
