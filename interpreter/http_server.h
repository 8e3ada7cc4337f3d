// The studio's HTTP: a listening socket on 127.0.0.1 only, and one request per connection, read with a
// size and time limit, answered and closed. Small on purpose: one page, its state, its runs and the output
// folder's files, for one person's browser on the same machine.
#pragma once

#include <chrono>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace selfsim::interp {

struct HttpRequest {
  std::string method, path, query, host;
  std::string origin, fetch_site;  // the Origin and Sec-Fetch-Site headers, where the browser sent them
};

// The request line and Host header of a request's head (up to the blank line); nullopt when malformed.
std::optional<HttpRequest> parse_http_request(std::string_view head);

// %XX (and, in a query, '+' for a space) undone; nullopt for a bad escape or a NUL byte.
std::optional<std::string> url_decoded(std::string_view text, bool query = true);

// A relative path as a URL path: every byte but letters, digits and -._~/=, percent-encoded.
std::string url_path(const std::string& path);

// "a=1&b=two" as {a: 1, b: two}, decoded; nullopt when a part does not decode.
std::optional<std::map<std::string, std::string>> query_values(std::string_view query);

class HttpListener {
 public:
  // Listens on 127.0.0.1:port (0: a free port). Throws Error naming the port when it cannot.
  explicit HttpListener(int port);
  ~HttpListener();
  HttpListener(const HttpListener&) = delete;
  HttpListener& operator=(const HttpListener&) = delete;
  int fd() const { return fd_; }
  int port() const { return port_; }

  // A connection whose request is still coming in. Connections are gathered side by side, so one that
  // sends slowly or nothing (a browser's preconnect, a slowloris) holds up no other.
  struct Connection {
    int fd = -1;
    bool local = false;  // the peer is this machine
    std::string head;
    std::chrono::steady_clock::time_point deadline;
  };
  // Accepts a waiting connection (non-blocking); false when there was none.
  bool accept_into(std::vector<Connection>& open);
  // Reads what a connection has sent. Returns its request once the head is complete; closes it (with a
  // 400 for a malformed or oversized head) and returns nullopt with fd = -1 when it is done with.
  static std::optional<HttpRequest> read_more(Connection& c);

 private:
  int fd_ = -1, port_ = 0;
};

// Writes a whole response and closes the connection.
void http_respond(int fd, int status, const std::string& type, std::string_view body);

}  // namespace selfsim::interp
