// UTF-8 text: whether it is well-formed (the names written into files other programs parse as UTF-8,
// ParaView's series files and the Python of view.py, must be), and how many characters it holds (the column
// a message names, as an editor counts it; how wide they show, for a caret, is text_width.h's).
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>

namespace selfsim::io {

// The bytes of the well-formed UTF-8 character (RFC 3629: no overlong forms, no surrogates, nothing above
// U+10FFFF) that starts at s[i], 1 to 4; 0 when none starts there.
inline std::size_t utf8_length(std::string_view s, std::size_t i) {
  const auto c = static_cast<unsigned char>(s[i]);
  std::size_t n = 0;
  unsigned lo = 0x80, hi = 0xbf;  // the allowed range of the second byte
  if (c < 0x80)
    n = 1;
  else if (c >= 0xc2 && c <= 0xdf)
    n = 2;
  else if (c == 0xe0)
    n = 3, lo = 0xa0;
  else if (c == 0xed)
    n = 3, hi = 0x9f;
  else if (c >= 0xe1 && c <= 0xef)
    n = 3;
  else if (c == 0xf0)
    n = 4, lo = 0x90;
  else if (c == 0xf4)
    n = 4, hi = 0x8f;
  else if (c >= 0xf1 && c <= 0xf3)
    n = 4;
  if (n == 0 || i + n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k) {
    const auto b = static_cast<unsigned char>(s[i + k]);
    if (b < (k == 1 ? lo : 0x80) || b > (k == 1 ? hi : 0xbf)) return 0;
  }
  return n;
}

// Well-formed UTF-8 throughout. Python refuses a source file with anything else in it.
inline bool valid_utf8(const std::string& s) {
  for (std::size_t i = 0; i < s.size();) {
    const std::size_t n = utf8_length(s, i);
    if (n == 0) return false;
    i += n;
  }
  return true;
}

// The characters text holds: one per UTF-8 character, one per byte that is not UTF-8 (a terminal shows it
// as one replacement character).
inline std::size_t shown_characters(std::string_view s) {
  std::size_t count = 0;
  for (std::size_t i = 0; i < s.size(); ++count) i += std::max<std::size_t>(utf8_length(s, i), 1);
  return count;
}

}  // namespace selfsim::io
