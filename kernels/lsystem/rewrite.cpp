#include "kernels/lsystem/rewrite.h"

#include "kernels/base/check.h"
#include "kernels/base/count_text.h"
#include "kernels/base/error.h"
#include "kernels/lsystem/production_count.h"

namespace selfsim::lsystem {

namespace {

// Appends every symbol to a string.
struct StringSink {
  std::string& out;
  std::size_t subtree(std::uint8_t, int) { return 0; }
  void symbol(std::uint8_t s) { out += static_cast<char>(s); }
  void progress() {}
};

}  // namespace

std::string expand_string(const Grammar& g, int level, double max_symbols) {
  g.validate();
  check_range(level, 0, max_level, "option 'level'");
  const double n = predict_counts(g, level).symbols;
  if (n > max_symbols)
    throw Error("level " + std::to_string(level) + " has " + count_text(n) + " symbols, over the limit of " +
                count_text(max_symbols) + " for a string");
  std::string s;
  s.reserve(static_cast<std::size_t>(n));
  StringSink sink{s};
  rewrite(Compiled(g), g.axiom, level, sink);
  return s;
}

}  // namespace selfsim::lsystem
