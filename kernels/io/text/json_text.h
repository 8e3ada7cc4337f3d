// Text into JSON: a string's content escaped ("name" : "a \"b\""), for the few JSON files selfsim writes
// (ParaView's .series, `selfsim params`, a sweep's manifest).
#pragma once

#include <charconv>
#include <cstdio>
#include <string>
#include <string_view>

#include "kernels/base/utf8.h"

namespace selfsim::io {

// JSON string content: quotes, backslashes and control characters escaped; other bytes as they are when
// the text is UTF-8, else each byte above 127 as the character of that number (JSON must be UTF-8).
inline std::string json_escaped(std::string_view text) {
  const bool utf8 = valid_utf8(std::string(text));
  std::string out;
  for (unsigned char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c < 0x20 || (c >= 0x80 && !utf8)) {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\u%04x", c);
      out += buffer;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

// A number as JSON: the shortest text that reads back to the same double ("0.30000000000000004", "1e-07").
inline std::string json_number(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

// The string as a quoted JSON string.
inline std::string json_string(std::string_view text) { return "\"" + json_escaped(text) + "\""; }

}  // namespace selfsim::io
