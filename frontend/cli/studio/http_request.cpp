#include "frontend/cli/studio/http_request.h"

#include <cctype>
#include <tuple>
#include <vector>

#include "kernels/io/text/hex_digit.h"

namespace selfsim::interp {

std::optional<std::string> url_decoded(std::string_view text, bool query) {
  std::string s;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '+' && query) {
      s += ' ';
    } else if (text[i] == '%') {
      if (i + 2 >= text.size()) return std::nullopt;
      const int hi = io::hex_digit(text[i + 1]), lo = io::hex_digit(text[i + 2]);
      if (hi < 0 || lo < 0) return std::nullopt;
      s += static_cast<char>(hi * 16 + lo);
      i += 2;
    } else {
      s += text[i];
    }
  }
  if (s.find('\0') != std::string::npos) return std::nullopt;
  return s;
}

std::optional<std::map<std::string, std::string>> query_values(std::string_view query) {
  std::map<std::string, std::string> values;
  while (!query.empty()) {
    const std::size_t amp = query.find('&');
    const std::string_view part = query.substr(0, amp);
    query = amp == std::string_view::npos ? std::string_view() : query.substr(amp + 1);
    if (part.empty()) continue;
    const std::size_t eq = part.find('=');
    const auto key = url_decoded(part.substr(0, eq));
    const auto value = url_decoded(eq == std::string_view::npos ? std::string_view() : part.substr(eq + 1));
    if (!key || !value) return std::nullopt;
    values[*key] = *value;
  }
  return values;
}

namespace {

bool token_char(unsigned char c) {
  return std::isalnum(c) || std::string_view("!#$%&'*+-.^_`|~").find(static_cast<char>(c)) != std::string_view::npos;
}

}  // namespace

std::size_t http_head_end(std::string_view data) {
  for (std::size_t at = data.find('\n'); at != std::string_view::npos; at = data.find('\n', at + 1)) {
    if (at + 1 < data.size() && data[at + 1] == '\n') return at + 2;
    if (at + 2 < data.size() && data[at + 1] == '\r' && data[at + 2] == '\n') return at + 3;
  }
  return std::string_view::npos;
}

std::optional<HttpRequest> parse_http_request(std::string_view head) {
  // Lines end in LF, with or without a CR before it; any other control byte (a bare CR, a NUL) makes the
  // request bad rather than being read one way here and another way elsewhere.
  std::vector<std::string_view> lines;
  for (std::size_t at = 0; at < head.size();) {
    std::size_t end = head.find('\n', at);
    if (end == std::string_view::npos) end = head.size();
    std::string_view line = head.substr(at, end - at);
    if (line.ends_with('\r')) line.remove_suffix(1);
    if (line.empty()) break;  // the end of the head
    for (unsigned char c : line)
      if ((c < 0x20 && c != '\t') || c == 0x7f) return std::nullopt;
    lines.push_back(line);
    at = end + 1;
  }
  if (lines.empty()) return std::nullopt;
  // METHOD SP target SP HTTP/1.x, exactly.
  const std::string_view line = lines[0];
  const std::size_t a = line.find(' '), b = a == std::string_view::npos ? a : line.find(' ', a + 1);
  if (a == 0 || b == std::string_view::npos || line.find(' ', b + 1) != std::string_view::npos) return std::nullopt;
  const std::string_view version = line.substr(b + 1);
  if (version != "HTTP/1.1" && version != "HTTP/1.0") return std::nullopt;
  HttpRequest r;
  r.method = std::string(line.substr(0, a));
  for (unsigned char c : r.method)
    if (!token_char(c)) return std::nullopt;
  const std::string_view target = line.substr(a + 1, b - a - 1);
  if (target.empty() || target[0] != '/') return std::nullopt;
  const std::size_t q = target.find('?');
  const auto path = url_decoded(target.substr(0, q), false);
  if (!path) return std::nullopt;
  r.path = *path;
  if (q != std::string_view::npos) r.query = std::string(target.substr(q + 1));
  bool seen_host = false, seen_origin = false, seen_site = false;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const std::string_view h = lines[i];
    // Header names are case-insensitive tokens right before the colon: "Origin :" or a folded line could be
    // read as another header than the one a check looks at, so they are refused.
    const std::size_t colon = h.find(':');
    if (colon == 0 || colon == std::string_view::npos) return std::nullopt;
    std::string name(h.substr(0, colon));
    for (char& c : name) {
      if (!token_char(static_cast<unsigned char>(c))) return std::nullopt;
      c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    std::string_view v = h.substr(colon + 1);
    while (!v.empty() && (v.front() == ' ' || v.front() == '\t')) v.remove_prefix(1);
    while (!v.empty() && (v.back() == ' ' || v.back() == '\t')) v.remove_suffix(1);
    // The headers the studio's checks read count only when there is exactly one, with a value: with two, a
    // check could read one and a browser or proxy have meant the other.
    for (auto [header, seen, field] :
         {std::tuple{"host", &seen_host, &r.host}, std::tuple{"origin", &seen_origin, &r.origin},
          std::tuple{"sec-fetch-site", &seen_site, &r.fetch_site}})
      if (name == header) {
        if (*seen || v.empty()) return std::nullopt;
        *seen = true;
        *field = std::string(v);
      }
  }
  return r;
}

}  // namespace selfsim::interp
