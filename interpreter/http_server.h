// The studio's HTTP: a listening socket on 127.0.0.1 only, and one request per connection, answered and
// closed (anything the client sends after its request is read and dropped, within bounds, so the close
// never resets the connection before the answer is through). Small on purpose: one page, its state, its runs and the
// output folder's files, for one person's browser on the same machine. Event-driven: every socket is non-blocking and
// the studio's one poll() waits on all of them, so a client that sends slowly, reads slowly or does nothing holds up no
// other client and never delays Ctrl-C; a file goes out piece by piece as its client takes it.
#pragma once

#include <poll.h>

#include <chrono>
#include <cstdint>
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

// Where a request's head ends: just past its first empty line, whether lines end in CRLF or a bare LF
// (RFC 9112 2.2 lets a server take either); npos while it has not come.
std::size_t http_head_end(std::string_view data);

// The request line and headers of a request's head (up to and with its empty line); nullopt when
// malformed: a bare CR or other control byte, a folded line, a header name that is no token or has space
// before its colon, or a Host, Origin or Sec-Fetch-Site that is repeated or empty (which one would count?).
std::optional<HttpRequest> parse_http_request(std::string_view head);

// %XX (and, in a query, '+' for a space) undone; nullopt for a bad escape or a NUL byte.
std::optional<std::string> url_decoded(std::string_view text, bool query = true);

// A relative path as a URL path: every byte but letters, digits and -._~/=, percent-encoded.
std::string url_path(const std::string& path);

// "a=1&b=two" as {a: 1, b: two}, decoded; nullopt when a part does not decode.
std::optional<std::map<std::string, std::string>> query_values(std::string_view query);

class HttpServer {
 public:
  using Id = long;  // a connection, never reused: an answer for one already closed goes nowhere
  struct Incoming {
    Id id;
    bool local;  // the peer is this machine
    HttpRequest request;
  };

  // Listens on 127.0.0.1:port (0: a free port). Throws Error naming the port when it cannot.
  explicit HttpServer(int port);
  ~HttpServer();
  HttpServer(const HttpServer&) = delete;
  HttpServer& operator=(const HttpServer&) = delete;
  int port() const { return port_; }

  // Appends what the server waits for to the caller's poll set: its listening socket, each connection still
  // sending its request (POLLIN) and each answer still going out (POLLOUT).
  void add_poll(std::vector<pollfd>& p);
  // After the poll: accepts, reads and writes what each socket takes without waiting, and closes the
  // connections past their limits. Returns the requests now complete, each to be answered once.
  std::vector<Incoming> step(const std::vector<pollfd>& p);
  // The answer to a request; it goes out as its client takes it, and the connection closes after it.
  void respond(Id id, int status, const std::string& type, std::string_view body);
  // A file's first `size` bytes as a 200 answer, read from the open `file` (which the server closes) piece
  // by piece as the client takes them: no file is held in memory whole.
  void respond_file(Id id, const std::string& type, int file, std::int64_t size);

 private:
  struct Connection;
  Connection* find(Id id);
  void accept_waiting();
  void read_request(Connection& c, std::vector<Incoming>& complete);
  void start_writing(Connection& c);
  void write_answer(Connection& c);
  // Reads and drops what the client sent after its request; false when that closed the connection.
  bool discard_input(Connection& c);
  void drain(Connection& c);         // the answer all queued: shut the sending side, read until the client closes
  bool still_taking(Connection& c);  // draining, the client has taken more of the answer since the last look
  void close(Connection& c);
  int fd_ = -1, port_ = 0;
  std::size_t listen_slot_ = 0;
  Id next_id_ = 1;
  std::vector<Connection> open_;
};

}  // namespace selfsim::interp
