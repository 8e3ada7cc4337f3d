// Text into JSON: a string's content escaped ("name" : "a \"b\""), for the few JSON files selfsim writes
// (ParaView's .series, `selfsim params`, a sweep's manifest).
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

namespace selfsim::io {

// JSON string content: quotes, backslashes and control characters escaped; other bytes (UTF-8) as they are.
inline std::string json_escaped(std::string_view text) {
  std::string out;
  for (unsigned char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c < 0x20) {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\u%04x", c);
      out += buffer;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

// The string as a quoted JSON string.
inline std::string json_string(std::string_view text) { return "\"" + json_escaped(text) + "\""; }

}  // namespace selfsim::io
