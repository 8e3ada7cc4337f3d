#include "interpreter/http_server.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>

#include "kernels/geom/error.h"

namespace selfsim::interp {

namespace {

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

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

}  // namespace

std::string url_path(const std::string& path) {
  std::string s;
  for (unsigned char c : path) {
    if (std::isalnum(c) || std::string_view("-._~/=,").find(static_cast<char>(c)) != std::string_view::npos) {
      s += static_cast<char>(c);
    } else {
      char buf[4];
      std::snprintf(buf, sizeof buf, "%%%02X", c);
      s += buf;
    }
  }
  return s;
}

std::optional<std::string> url_decoded(std::string_view text, bool query) {
  std::string s;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '+' && query) {
      s += ' ';
    } else if (text[i] == '%') {
      if (i + 2 >= text.size()) return std::nullopt;
      const int hi = hex_digit(text[i + 1]), lo = hex_digit(text[i + 2]);
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

std::optional<HttpRequest> parse_http_request(std::string_view head) {
  const std::size_t line_end = head.find("\r\n");
  if (line_end == std::string_view::npos) return std::nullopt;
  const std::string_view line = head.substr(0, line_end);
  const std::size_t a = line.find(' '), b = line.rfind(' ');
  if (a == std::string_view::npos || b <= a || !line.substr(b + 1).starts_with("HTTP/1.")) return std::nullopt;
  HttpRequest r;
  r.method = std::string(line.substr(0, a));
  const std::string_view target = line.substr(a + 1, b - a - 1);
  if (target.empty() || target[0] != '/') return std::nullopt;
  const std::size_t q = target.find('?');
  const auto path = url_decoded(target.substr(0, q), false);
  if (!path) return std::nullopt;
  r.path = *path;
  if (q != std::string_view::npos) r.query = std::string(target.substr(q + 1));
  for (std::size_t at = line_end + 2; at < head.size();) {
    const std::size_t end = head.find("\r\n", at);
    const std::string_view h = head.substr(at, end == std::string_view::npos ? std::string_view::npos : end - at);
    // Header names are case-insensitive; a second Host makes the request bad (which one would count?).
    const std::size_t colon = h.find(':');
    if (colon != std::string_view::npos) {
      std::string name(h.substr(0, colon));
      for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      std::string_view v = h.substr(colon + 1);
      while (!v.empty() && v.front() == ' ') v.remove_prefix(1);
      while (!v.empty() && v.back() == ' ') v.remove_suffix(1);
      if (name == "host") {
        if (!r.host.empty()) return std::nullopt;
        r.host = std::string(v);
      } else if (name == "origin") {
        r.origin = std::string(v);
      } else if (name == "sec-fetch-site") {
        r.fetch_site = std::string(v);
      }
    }
    if (end == std::string_view::npos) break;
    at = end + 2;
  }
  return r;
}

HttpListener::HttpListener(int port) {
  fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);  // accept never waits
  if (fd_ < 0) throw Error(std::string("cannot open a socket: ") + std::strerror(errno));
  const int yes = 1;
  ::setsockopt(fd_, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(static_cast<std::uint16_t>(port));
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);  // this machine only: never another address
  if (::bind(fd_, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0 || ::listen(fd_, 16) != 0) {
    const std::string why = std::strerror(errno);
    ::close(fd_);
    throw Error("cannot listen on 127.0.0.1:" + std::to_string(port) + ": " + why);
  }
  socklen_t len = sizeof addr;
  ::getsockname(fd_, reinterpret_cast<sockaddr*>(&addr), &len);
  port_ = ntohs(addr.sin_port);
}

HttpListener::~HttpListener() {
  if (fd_ >= 0) ::close(fd_);
}

bool HttpListener::accept_into(std::vector<Connection>& open) {
  sockaddr_in peer{};
  socklen_t len = sizeof peer;
  Connection c;
  c.fd = ::accept4(fd_, reinterpret_cast<sockaddr*>(&peer), &len, SOCK_CLOEXEC | SOCK_NONBLOCK);
  if (c.fd < 0) return false;
  c.local = peer.sin_family == AF_INET && ntohl(peer.sin_addr.s_addr) == INADDR_LOOPBACK;
  c.deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  // An answer may wait at most 2 s for a client that does not read it.
  const timeval send_limit{2, 0};
  ::setsockopt(c.fd, SOL_SOCKET, SO_SNDTIMEO, &send_limit, sizeof send_limit);
  if (open.size() >= 64) {  // the oldest quiet connection makes room
    ::close(open.front().fd);
    open.erase(open.begin());
  }
  open.push_back(std::move(c));
  return true;
}

std::optional<HttpRequest> HttpListener::read_more(Connection& c) {
  char buf[4096];
  for (;;) {
    const ssize_t n = ::read(c.fd, buf, sizeof buf);
    if (n > 0) {
      c.head.append(buf, static_cast<std::size_t>(n));
      if (c.head.size() > 16384) break;
      continue;
    }
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) break;
    ::close(c.fd);  // closed by the client, or an error
    c.fd = -1;
    return std::nullopt;
  }
  const std::size_t end = c.head.find("\r\n\r\n");
  if (end == std::string::npos && c.head.size() <= 16384) return std::nullopt;  // more to come
  std::optional<HttpRequest> r =
      end == std::string::npos ? std::nullopt : parse_http_request(c.head.substr(0, end + 2));
  if (!r) {
    http_respond(c.fd, 400, "text/plain", "bad request\n");
    c.fd = -1;
  }
  return r;
}

void http_respond(int fd, int status, const std::string& type, std::string_view body) {
  // Blocking from here, so SO_SNDTIMEO bounds how long a client that does not read can hold the answer.
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  const std::string head =
      "HTTP/1.1 " + std::to_string(status) + " " + reason(status) + "\r\nContent-Type: " + type +
      "\r\nContent-Length: " + std::to_string(body.size()) +
      "\r\nCache-Control: no-store\r\nX-Content-Type-Options: nosniff\r\nConnection: close\r\n\r\n";
  for (std::string_view part : {std::string_view(head), body}) {
    while (!part.empty()) {
      const ssize_t n = ::send(fd, part.data(), part.size(), MSG_NOSIGNAL);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;  // the client went away, or did not read for 2 s (SO_SNDTIMEO)
      part.remove_prefix(static_cast<std::size_t>(n));
    }
  }
  ::close(fd);
}

}  // namespace selfsim::interp
