// Whole-string number parsing for command-line values and --set overrides: "12" yes, "12x", "" and
// (for floating point) "nan"/"inf" no.
#pragma once

#include <charconv>
#include <cmath>
#include <optional>
#include <string_view>
#include <type_traits>

namespace selfsim::interp {

template <class T>
std::optional<T> parse_text(std::string_view s) {
  T v{};
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size()) return std::nullopt;
  if constexpr (std::is_floating_point_v<T>)
    if (!std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace selfsim::interp
