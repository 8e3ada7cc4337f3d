// Reading the studio's HTTP requests: where a head ends, its request line and the headers the studio's checks
// read, and URL paths and queries. Strict on purpose: anything a browser or proxy could read another way is
// refused rather than guessed at.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace selfsim::interp {

struct HttpRequest {
  std::string method, path, query, host;
  std::string origin, fetch_site;  // the Origin and Sec-Fetch-Site headers, where the browser sent them
};

// Where a request's head ends: just past its first empty line, whether lines end in CRLF or a bare LF
// (RFC 9112 2.2 lets a server take either); npos while it has not come.
std::size_t http_head_end(std::string_view data);

// The request line and headers of a request's head (up to and with its empty line); nullopt when
// malformed: a bare CR or other control byte, a folded line, a header name that is no token or has space
// before its colon, or a Host, Origin or Sec-Fetch-Site that is repeated or empty (which one would count?).
std::optional<HttpRequest> parse_http_request(std::string_view head);

// %XX (and, in a query, '+' for a space) undone; nullopt for a bad escape or a NUL byte.
std::optional<std::string> url_decoded(std::string_view text, bool query = true);

// "a=1&b=two" as {a: 1, b: two}, decoded; nullopt when a part does not decode.
std::optional<std::map<std::string, std::string>> query_values(std::string_view query);

}  // namespace selfsim::interp
