// Finding a token of a rule's text outside parentheses: the arrow or the ':' of a rule, never one inside a
// module's parameters ("A(x:y) : x > 1 -> ..."). Shared by selfsim's rule parser and the book's notation.
#pragma once

#include <cstddef>
#include <string_view>

namespace selfsim::lsystem {

// Position of `what` in `text` outside parentheses, the first (or with `last` the last) one, or npos.
inline std::size_t find_outside(std::string_view text, std::string_view what, bool last = false) {
  std::size_t found = std::string_view::npos;
  int depth = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (depth == 0 && text.substr(i, what.size()) == what) {
      if (!last) return i;
      found = i;
    }
    depth += text[i] == '(' ? 1 : text[i] == ')' ? -1 : 0;
  }
  return found;
}

}  // namespace selfsim::lsystem
