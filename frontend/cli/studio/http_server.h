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
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "frontend/cli/studio/http_request.h"

namespace selfsim::interp {

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
