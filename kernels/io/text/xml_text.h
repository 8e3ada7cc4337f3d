// Small pieces shared by the streaming XML scanners of the readers (vtk_header_check.cpp, svg_read.cpp) and
// the writers of XML text (series_file.cpp).
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>

#include "kernels/base/utf8.h"

namespace selfsim::io {

inline bool xml_space(int c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// Streaming search for `end` (at most 4 characters: "-->", "?>", "]]>"): given how many of its first
// characters the text seen so far ends with, returns that count after character c.
inline std::size_t advance_match(std::string_view end, std::size_t matched, char c) {
  char seen[5];
  for (std::size_t i = 0; i < matched; ++i) seen[i] = end[i];
  seen[matched] = c;
  const std::string_view s(seen, matched + 1);
  for (std::size_t k = std::min(s.size(), end.size()); k > 0; --k)
    if (s.substr(s.size() - k) == end.substr(0, k)) return k;
  return 0;
}

// The text of an attribute value or element with xml_escaped's entities undone (&amp; last, so "&amp;lt;"
// stays "&lt;").
inline std::string xml_unescaped(std::string value) {
  for (const auto& [from, to] :
       {std::pair<std::string_view, std::string_view>{"&quot;", "\""}, {"&lt;", "<"}, {"&gt;", ">"}, {"&amp;", "&"}})
    for (std::size_t e = value.find(from); e != std::string::npos; e = value.find(from, e + to.size()))
      value.replace(e, from.size(), to);
  return value;
}

// The bytes of the character at s[i] when XML 1.0 holds it as written, 1 to 4; 0 when it does not: a byte
// that starts no well-formed UTF-8 character, a control character (tab, LF and CR too: XML allows them,
// but an attribute reads them as spaces, so no name keeps them) or U+FFFE / U+FFFF. A parser stops at the first
// such character ("not well-formed"); no escape helps, as &#xFF; would name the character U+00FF, not the
// byte of a file name.
inline std::size_t xml_character_length(std::string_view s, std::size_t i) {
  const std::size_t n = utf8_length(s, i);
  if (n == 0 || static_cast<unsigned char>(s[i]) < 0x20) return 0;
  if (n == 3 && s.substr(i, 2) == "\xEF\xBF" && static_cast<unsigned char>(s[i + 2]) >= 0xBE) return 0;
  return n;
}

// Whether XML holds every character of `text` as written (xml_character_length): a file name that a .pvd's
// file= must give byte for byte, or no .pvd can name that file.
inline bool xml_holds(std::string_view text) {
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = xml_character_length(text, i);
    if (n == 0) return false;
    i += n;
  }
  return true;
}

// `text` for reading only (an SVG caption): each byte XML cannot hold shown as '?'.
inline std::string xml_shown(std::string_view text) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = xml_character_length(text, i);
    out += n == 0 ? std::string_view("?") : text.substr(i, n);
    i += n == 0 ? 1 : n;
  }
  return out;
}

// Text for an XML attribute value in double quotes.
inline std::string xml_escaped(std::string_view text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace selfsim::io
