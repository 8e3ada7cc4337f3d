// The studio's HTTP: a listening socket on 127.0.0.1 only, and one request per connection, read with a
// size and time limit, answered and closed. Small on purpose: one page, its state, its runs and the output
// folder's files, for one person's browser on the same machine.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace selfsim::interp {

struct HttpRequest {
  std::string method, path, query, host;
};

// The request line and Host header of a request's head (up to the blank line); nullopt when malformed.
std::optional<HttpRequest> parse_http_request(std::string_view head);

// %XX and '+' undone; nullopt for a bad escape or a NUL byte.
std::optional<std::string> url_decoded(std::string_view text);

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

  // Accepts a connection and reads its request's head (at most 16 KiB, 2 s). Returns the connection's
  // descriptor (to answer on, then close) and the request, or nullopt (a bad request gets its 400 here).
  // `local` is false when the peer is not this machine.
  struct Accepted {
    int fd = -1;
    bool local = false;
    std::optional<HttpRequest> request;
  };
  Accepted accept_one();

 private:
  int fd_ = -1, port_ = 0;
};

// Writes a whole response and closes the connection.
void http_respond(int fd, int status, const std::string& type, std::string_view body);

}  // namespace selfsim::interp
