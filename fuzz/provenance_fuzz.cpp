// Fuzz target: the provenance parser (kernels/io/provenance/provenance_parse.cpp), which `selfsim info` and `selfsim
// rerun` run on the record any file may carry. Only selfsim::Error may escape. A record that parses holds
// no NUL in any string (a path cut at a NUL would run another file), and writing it again with
// provenance_json reads back the same record (what selfsim writes, it reads whole). Its seed is one
// --seed takes (rerun passes it on).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>

#include "fuzz/fuzz_support.h"
#include "kernels/base/error.h"
#include "kernels/io/provenance/provenance.h"

namespace {

bool no_nul(const std::string& s) { return s.find('\0') == std::string::npos; }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace selfsim;
  static const bool verbose = fuzz::env_flag("SELFSIM_FUZZ_VERBOSE");
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::optional<io::Provenance> p;
  try {
    p = io::parse_provenance(text);
  } catch (const Error& e) {
    if (verbose) std::fprintf(stderr, "refused: %s\n", e.what());
    return 0;
  } catch (...) {
    fuzz::unexpected_exception("io::parse_provenance");
  }
  if (!p) return 0;
  if (verbose) std::fprintf(stderr, "read: recipe of %zu bytes, %zu --set values\n", p->recipe.size(), p->sets.size());
  fuzz::require(!p->recipe.empty(), "a record without a recipe was accepted");
  fuzz::require(p->seed >= 0, "a seed --seed would refuse was accepted");
  fuzz::require(no_nul(p->recipe) && no_nul(p->name) && no_nul(p->version) && no_nul(p->sha256), "a field holds a NUL");
  for (const auto& [k, v] : p->sets) fuzz::require(no_nul(k) && no_nul(v), "a --set key or value holds a NUL");
  std::optional<io::Provenance> again;
  try {
    again = io::parse_provenance(io::provenance_json(*p));
  } catch (...) {
    fuzz::finding("what provenance_json wrote of a parsed record is refused");
  }
  fuzz::require(again.has_value(), "what provenance_json wrote of a parsed record is no record");
  fuzz::require(again->version == p->version && again->recipe == p->recipe && again->sha256 == p->sha256 &&
                    again->sets == p->sets && again->seed == p->seed && again->name == p->name,
                "a parsed record written again reads back different");
  return 0;
}
