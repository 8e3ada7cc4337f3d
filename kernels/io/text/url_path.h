// A relative path as a URL path, for the links selfsim writes (a sweep's contact sheets) and serves (the
// studio): every byte but letters, digits and `-._~/=,` is percent-encoded.
#pragma once

#include <cctype>
#include <cstdio>
#include <string>
#include <string_view>

namespace selfsim::io {

inline std::string url_path(const std::string& path) {
  std::string s;
  for (unsigned char c : path) {
    if (std::isalnum(c) || std::string_view("-._~/=,").find(static_cast<char>(c)) != std::string_view::npos) {
      s += static_cast<char>(c);
    } else {
      char buf[4];
      std::snprintf(buf, sizeof buf, "%%%02X", c);
      s += buf;
    }
  }
  return s;
}

}  // namespace selfsim::io
