// What every fuzz target shares: how a finding is reported. A finding prints one line starting with
// "FUZZ-FINDING:" (fuzz/run.sh groups findings by it) and aborts, which libFuzzer and the replay driver
// both report as a crash with this input.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <typeinfo>

namespace selfsim::fuzz {

[[noreturn]] inline void finding(const std::string& what) {
  std::fprintf(stderr, "FUZZ-FINDING: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

// True when environment variable `name` is set to something other than "" or "0".
inline bool env_flag(const char* name) {
  const char* v = std::getenv(name);
  return v != nullptr && v[0] != '\0' && std::string(v) != "0";
}

// Checks an invariant the code under test promises.
inline void require(bool ok, const std::string& what) {
  if (!ok) finding("invariant broken: " + what);
}

// For catch (...) after catch (const selfsim::Error&): anything else escaping the code under test.
[[noreturn]] inline void unexpected_exception(const char* where) {
  try {
    throw;
  } catch (const std::exception& e) {
    finding(std::string(where) + " threw " + typeid(e).name() + " (not selfsim::Error): " + e.what());
  } catch (...) {
    finding(std::string(where) + " threw a non-standard exception (not selfsim::Error)");
  }
}

}  // namespace selfsim::fuzz
