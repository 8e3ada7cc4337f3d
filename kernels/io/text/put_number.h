// Numbers into text formats (SVG, EPS): the shortest form to `digits` significant digits, locale-free.
// Nine are well below a pixel or a printer dot at any sensible zoom, and make far smaller files than 17.
#pragma once

#include <charconv>
#include <string>

namespace selfsim::io {

inline void put_number(std::string& s, double v, int digits = 9) {
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, digits);
  s.append(buf, r.ptr);
}

}  // namespace selfsim::io
