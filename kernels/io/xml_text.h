// Small pieces shared by the streaming XML scanners of the readers (vtk_header_check.cpp, svg_read.cpp) and
// the writers of XML text (series_file.cpp).
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>

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
