#include "frontend/lua/option_hints.h"

#include <algorithm>
#include <array>
#include <string_view>

namespace selfsim::interp {

namespace {

struct OptionHint {
  std::string_view unknown;  // the name a user may try
  std::string_view meant;    // the option that does its work: the hint is given only where it is read
  std::string_view text;     // "{}" stands for the value given (or "e" when it is no number)
};

// ABOP's tropism (section 2.2) is a vector T and an elasticity e; selfsim's `tropism` is e*T, one vector.
constexpr std::string_view tropism_text = "the tropism vector's length is its elasticity: tropism = { 0, -{}, 0 }";
constexpr std::array hints = {
    OptionHint{"elasticity", "tropism", tropism_text},
    OptionHint{"elastic", "tropism", tropism_text},
    OptionHint{"e", "tropism", tropism_text},
    OptionHint{"susceptibility", "tropism", tropism_text},
};

}  // namespace

std::string option_hint(const std::string& unknown, const std::vector<std::string>& known, const std::string& value) {
  for (const OptionHint& h : hints) {
    if (h.unknown != unknown || std::find(known.begin(), known.end(), h.meant) == known.end()) continue;
    std::string text(h.text);
    if (const std::size_t at = text.find("{}"); at != std::string::npos)
      text.replace(at, 2, value.empty() ? "e" : value.starts_with('-') ? value.substr(1) : value);
    return text;
  }
  return "";
}

}  // namespace selfsim::interp
