// The value of one hexadecimal digit, as JSON's \u escapes, URL %-escapes and #rrggbb colours write them.
#pragma once

namespace selfsim::io {

// 0 to 15 for 0-9, a-f and A-F; -1 for any other byte.
inline int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

}  // namespace selfsim::io
