#include "frontend/cli/studio/http_server.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <linux/sockios.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>

#include "kernels/base/error.h"

namespace selfsim::interp {

namespace {

const char* reason(int status) {
  switch (status) {
    case 200:
      return "OK";
    case 400:
      return "Bad Request";
    case 403:
      return "Forbidden";
    case 404:
      return "Not Found";
    case 405:
      return "Method Not Allowed";
    default:
      return "Error";
  }
}

// Limits that keep one client from holding the studio's memory or its loop.
constexpr std::size_t max_head = 16384;                 // a request's head, in bytes
constexpr std::size_t max_connections = 128;            // open at once; the oldest still-reading one makes room
constexpr std::size_t turn_bytes = 1 << 20;             // sent to one client per loop turn, so others get theirs
constexpr std::size_t file_piece = 64 << 10;            // read from a file at a time
constexpr std::size_t max_discard = 1 << 20;            // read and dropped after a request (a second one, a body)
constexpr auto head_time = std::chrono::seconds(10);    // for the whole head to come in
constexpr auto stall_time = std::chrono::seconds(5);    // an answer's client taking nothing of it (or not closing)
constexpr auto answer_time = std::chrono::seconds(60);  // for the studio to answer (long polls: 20 s)

using Clock = std::chrono::steady_clock;

std::string answer_head(int status, const std::string& type, std::int64_t length) {
  return "HTTP/1.1 " + std::to_string(status) + " " + reason(status) + "\r\nContent-Type: " + type +
         "\r\nContent-Length: " + std::to_string(length) +
         "\r\nCache-Control: no-store\r\nX-Content-Type-Options: nosniff\r\nConnection: close\r\n\r\n";
}

}  // namespace

struct HttpServer::Connection {
  // draining: the whole answer is with the kernel and the sending side shut; what the client still sends is
  // read and dropped until it closes, so the answer's queued tail is not lost to a reset.
  enum class Stage { reading, answering, writing, draining };
  Id id = 0;
  int fd = -1;
  bool local = false;
  Stage stage = Stage::reading;
  std::string in;        // the head as it came so far
  std::string out;       // bytes of the answer read and not yet sent
  std::size_t sent = 0;  // of out
  int file = -1;         // the rest of the answer, where it is a file
  std::int64_t file_at = 0, file_left = 0;
  bool peer_closed = false;    // the client's sending side ended: nothing more to read
  std::size_t discarded = 0;   // bytes read and dropped after the request
  int unacked = 0;             // draining: answer bytes the client had not yet taken, at the last look
  Clock::time_point deadline;  // the limit of the current stage
  std::size_t slot = 0;        // in the poll set, or npos when not polled
};

HttpServer::HttpServer(int port) {
  fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);  // accept never waits
  if (fd_ < 0) throw Error(std::string("cannot open a socket: ") + std::strerror(errno));
  const int yes = 1;
  ::setsockopt(fd_, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(static_cast<std::uint16_t>(port));
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);  // this machine only: never another address
  if (::bind(fd_, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0 || ::listen(fd_, 64) != 0) {
    const std::string why = std::strerror(errno);
    ::close(fd_);
    throw Error("cannot listen on 127.0.0.1:" + std::to_string(port) + ": " + why);
  }
  socklen_t len = sizeof addr;
  ::getsockname(fd_, reinterpret_cast<sockaddr*>(&addr), &len);
  port_ = ntohs(addr.sin_port);
}

HttpServer::~HttpServer() {
  for (Connection& c : open_) close(c);
  if (fd_ >= 0) ::close(fd_);
}

void HttpServer::close(Connection& c) {
  if (c.fd >= 0) ::close(c.fd);
  if (c.file >= 0) ::close(c.file);
  c.fd = c.file = -1;
}

HttpServer::Connection* HttpServer::find(Id id) {
  for (Connection& c : open_)
    if (c.id == id && c.fd >= 0) return &c;
  return nullptr;
}

void HttpServer::add_poll(std::vector<pollfd>& p) {
  std::erase_if(open_, [](const Connection& c) { return c.fd < 0; });
  listen_slot_ = p.size();
  p.push_back({fd_, POLLIN, 0});
  for (Connection& c : open_) {
    c.slot = std::string::npos;  // an answer being made waits on the studio, not on its socket
    if (c.stage == Connection::Stage::answering) continue;
    c.slot = p.size();
    // An answer going out also reads (and drops) what its client sends meanwhile, so the client's sending
    // never stalls on a full buffer and nothing is left unread at the close.
    short events = c.stage == Connection::Stage::writing ? POLLOUT : POLLIN;
    if (c.stage == Connection::Stage::writing && !c.peer_closed) events |= POLLIN;
    p.push_back({c.fd, events, 0});
  }
}

void HttpServer::accept_waiting() {
  for (int i = 0; i < 64; ++i) {  // a flood of connections still leaves the loop its turn
    sockaddr_in peer{};
    socklen_t len = sizeof peer;
    const int fd = ::accept4(fd_, reinterpret_cast<sockaddr*>(&peer), &len, SOCK_CLOEXEC | SOCK_NONBLOCK);
    if (fd < 0) return;
    std::erase_if(open_, [](const Connection& c) { return c.fd < 0; });
    if (open_.size() >= max_connections) {
      // Room is made by the oldest connection still sending its request (a slowloris), else by the answer
      // whose client has taken the least lately; an answer the studio is making is never dropped.
      auto victim = std::find_if(open_.begin(), open_.end(),
                                 [](const Connection& c) { return c.stage == Connection::Stage::reading; });
      if (victim == open_.end())
        for (auto it = open_.begin(); it != open_.end(); ++it)
          if ((it->stage == Connection::Stage::writing || it->stage == Connection::Stage::draining) &&
              (victim == open_.end() || it->deadline < victim->deadline))
            victim = it;
      if (victim == open_.end()) {
        ::close(fd);
        continue;
      }
      close(*victim);
      open_.erase(victim);
    }
    Connection c;
    c.id = next_id_++;
    c.fd = fd;
    c.local = peer.sin_family == AF_INET && ntohl(peer.sin_addr.s_addr) == INADDR_LOOPBACK;
    c.deadline = Clock::now() + head_time;
    c.slot = std::string::npos;
    open_.push_back(std::move(c));
  }
}

void HttpServer::read_request(Connection& c, std::vector<Incoming>& complete) {
  char buf[4096];
  for (;;) {
    const ssize_t n = ::read(c.fd, buf, sizeof buf);
    if (n > 0) {
      c.in.append(buf, static_cast<std::size_t>(n));
      if (c.in.size() > max_head) break;
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) break;
    if (n == 0 && http_head_end(c.in) != std::string::npos) {  // a whole request, then half-closed
      c.peer_closed = true;
      break;
    }
    return close(c);  // closed by the client before its request was whole, or an error
  }
  const std::size_t end = http_head_end(c.in);
  if (end == std::string::npos && c.in.size() <= max_head) return;  // more to come
  std::optional<HttpRequest> r = end == std::string::npos || end > max_head
                                     ? std::nullopt
                                     : parse_http_request(std::string_view(c.in).substr(0, end));
  c.in.clear();
  c.stage = Connection::Stage::answering;
  c.deadline = Clock::now() + answer_time;
  if (!r) return respond(c.id, 400, "text/plain", "bad request\n");
  complete.push_back({c.id, c.local, std::move(*r)});
}

void HttpServer::write_answer(Connection& c) {
  std::size_t budget = turn_bytes;
  while (budget > 0) {
    if (c.sent == c.out.size()) {
      c.out.clear();
      c.sent = 0;
      if (c.file_left == 0) return drain(c);  // all sent
      c.out.resize(static_cast<std::size_t>(std::min<std::int64_t>(c.file_left, file_piece)));
      const ssize_t n = ::pread(c.file, c.out.data(), c.out.size(), c.file_at);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return close(c);  // the file shrank or failed: the client sees the answer cut short
      c.out.resize(static_cast<std::size_t>(n));
      c.file_at += n;
      c.file_left -= n;
    }
    const std::size_t want = std::min(c.out.size() - c.sent, budget);
    const ssize_t n = ::send(c.fd, c.out.data() + c.sent, want, MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return;  // its buffer is full: poll says when not
    if (n <= 0) return close(c);                                     // the client went away
    c.sent += static_cast<std::size_t>(n);
    budget -= static_cast<std::size_t>(n);
    c.deadline = Clock::now() + stall_time;  // it took something: it may take its time with the rest
  }
}

bool HttpServer::discard_input(Connection& c) {
  char buf[16384];
  while (!c.peer_closed) {
    const ssize_t n = ::read(c.fd, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return true;
    if (n == 0) {
      c.peer_closed = true;
      break;
    }
    c.discarded += n > 0 ? static_cast<std::size_t>(n) : 0;
    if (n < 0 || c.discarded > max_discard) {  // reset by the client, or sending without end
      close(c);
      return false;
    }
  }
  if (c.stage == Connection::Stage::draining) close(c);  // it has closed after taking the answer: a clean end
  return true;
}

void HttpServer::drain(Connection& c) {
  // A close with input unread makes the kernel send a reset, which drops the answer's tail still queued
  // for the client. So the sending side is shut (a FIN follows the answer) and the socket stays open for
  // reading until the client closes, it sends over max_discard, or it stops taking the answer.
  if (c.peer_closed) return close(c);  // all read already: a plain close ends cleanly
  ::shutdown(c.fd, SHUT_WR);
  c.stage = Connection::Stage::draining;
  c.deadline = Clock::now() + stall_time;
  if (::ioctl(c.fd, SIOCOUTQ, &c.unacked) != 0) c.unacked = 0;
}

bool HttpServer::still_taking(Connection& c) {
  int unacked = 0;
  if (c.stage != Connection::Stage::draining || ::ioctl(c.fd, SIOCOUTQ, &unacked) != 0) return false;
  const bool taking = unacked > 0 && unacked < c.unacked;  // a slow client still reading the tail
  c.unacked = unacked;
  return taking;
}

std::vector<HttpServer::Incoming> HttpServer::step(const std::vector<pollfd>& p) {
  std::vector<Incoming> complete;
  for (Connection& c : open_) {
    if (c.fd < 0 || c.slot >= p.size() || p[c.slot].fd != c.fd || p[c.slot].revents == 0) continue;
    if (c.stage == Connection::Stage::reading) {
      read_request(c, complete);
    } else if (c.stage == Connection::Stage::writing) {
      if (discard_input(c)) write_answer(c);
    } else if (c.stage == Connection::Stage::draining) {
      discard_input(c);
    }
  }
  if (listen_slot_ < p.size() && p[listen_slot_].fd == fd_ && (p[listen_slot_].revents & POLLIN)) accept_waiting();
  const auto now = Clock::now();
  for (Connection& c : open_)  // a head not whole in time, an answer not taken, a client not closing after it
    if (c.fd >= 0 && c.deadline <= now) {
      if (still_taking(c))
        c.deadline = now + stall_time;
      else
        close(c);
    }
  std::erase_if(open_, [](const Connection& c) { return c.fd < 0; });
  return complete;
}

void HttpServer::respond(Id id, int status, const std::string& type, std::string_view body) {
  Connection* c = find(id);
  if (!c || c->stage != Connection::Stage::answering) return;  // closed meanwhile, or answered
  c->out = answer_head(status, type, static_cast<std::int64_t>(body.size()));
  c->out += body;
  start_writing(*c);
}

void HttpServer::respond_file(Id id, const std::string& type, int file, std::int64_t size) {
  Connection* c = find(id);
  if (!c || c->stage != Connection::Stage::answering) {
    ::close(file);
    return;
  }
  c->out = answer_head(200, type, size);
  c->file = file;
  c->file_at = 0;
  c->file_left = size;
  start_writing(*c);
}

void HttpServer::start_writing(Connection& c) {
  c.sent = 0;
  c.stage = Connection::Stage::writing;
  c.deadline = Clock::now() + stall_time;
  write_answer(c);  // most answers fit the socket's buffer at once
}

}  // namespace selfsim::interp
