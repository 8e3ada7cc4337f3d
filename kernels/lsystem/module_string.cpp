#include "kernels/lsystem/module_string.h"

#include <charconv>

namespace selfsim::lsystem {

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

}  // namespace selfsim::lsystem
