#include "kernels/lsystem/module_string.h"

#include <charconv>

#include "kernels/base/count_text.h"
#include "kernels/base/error.h"
#include "kernels/lsystem/module_rewrite.h"

namespace selfsim::lsystem {

namespace {

struct TextSink : ModuleSink {
  std::string text;
  double max_modules;
  double count = 0;
  int level;
  void module(std::uint8_t s, std::span<const double> args) override {
    text += module_text(s, args);
    // Parameters print up to 24 bytes each: the text is bounded too, not only the count.
    if (++count > max_modules || static_cast<double>(text.size()) > 8 * max_modules)
      throw Error("level " + std::to_string(level) + " has more than " + count_text(max_modules) + " modules (or " +
                  count_text(8 * max_modules) + " bytes of text), over the limit for a string");
  }
};

}  // namespace

std::string module_text(std::uint8_t symbol, std::span<const double> args) {
  std::string out(1, static_cast<char>(symbol));
  if (args.empty()) return out;
  char buffer[32];
  for (std::size_t k = 0; k < args.size(); ++k) {
    out += k == 0 ? '(' : ',';
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, args[k]);  // shortest exact form
    out.append(buffer, ec == std::errc() ? end : buffer);
  }
  out += ')';
  return out;
}

std::string module_string_text(const Grammar& g, int level, double max_modules, Progress& progress) {
  TextSink sink;
  sink.max_modules = max_modules;
  sink.level = level;
  // A string is small: its derivation may hold and do no more than its text could be.
  rewrite_modules(g, level, sink, {.work = 64 * max_modules, .held = max_modules}, progress);
  return std::move(sink.text);
}

}  // namespace selfsim::lsystem
