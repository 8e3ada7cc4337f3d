// The one shape of a reading error, "cannot read 'FILE': REASON", kept to one line whatever the file's name
// or the reason hold (control characters become '?'), so `selfsim info` and `diff` print exactly one line.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace selfsim::io {

inline std::string one_line(std::string text) {
  for (char& c : text)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  return text;
}

// Text from a file quoted in a message: one line, cut after 40 bytes.
inline std::string shown(std::string_view v) {
  std::string s = one_line(std::string(v.substr(0, 40)));
  return v.size() > 40 ? s + "..." : s;
}

inline std::string cannot_read(const std::filesystem::path& file, const std::string& reason) {
  return "cannot read '" + one_line(file.string()) + "': " + one_line(reason);
}

}  // namespace selfsim::io
