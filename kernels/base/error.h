// The one exception type kernels throw for bad input or impossible requests. The message names the option
// or input at fault ("option 'level' must be ..."); the interpreter prefixes the recipe file:line.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace selfsim {

struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// An error with lines to show under its one-line message, such as a rule with a caret under the fault.
struct DetailedError : Error {
  std::string detail;
  DetailedError(const std::string& message, std::string detail) : Error(message), detail(std::move(detail)) {}
};

// Thrown by kernels when Progress::cancelled() became true (Ctrl-C, --timeout).
struct Cancelled : Error {
  Cancelled() : Error("cancelled") {}
};

// "'a', 'b', 'c'": the valid values, for messages about a wrong one.
inline std::string quoted_list(const std::vector<std::string>& items) {
  std::string s;
  for (const auto& i : items) s += (s.empty() ? "'" : ", '") + i + "'";
  return s;
}

}  // namespace selfsim
