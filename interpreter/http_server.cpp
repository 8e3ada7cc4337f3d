#include "interpreter/http_server.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
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

std::optional<std::string> url_decoded(std::string_view text) {
  std::string s;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '+') {
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
  const auto path = url_decoded(target.substr(0, q));
  if (!path) return std::nullopt;
  r.path = *path;
  if (q != std::string_view::npos) r.query = std::string(target.substr(q + 1));
  for (std::size_t at = line_end + 2; at < head.size();) {
    const std::size_t end = head.find("\r\n", at);
    const std::string_view h = head.substr(at, end == std::string_view::npos ? std::string_view::npos : end - at);
    if (h.size() > 5 && (h.substr(0, 5) == "Host:" || h.substr(0, 5) == "host:")) {
      std::string_view v = h.substr(5);
      while (!v.empty() && v.front() == ' ') v.remove_prefix(1);
      while (!v.empty() && v.back() == ' ') v.remove_suffix(1);
      r.host = std::string(v);
    }
    if (end == std::string_view::npos) break;
    at = end + 2;
  }
  return r;
}

HttpListener::HttpListener(int port) {
  fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
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

HttpListener::Accepted HttpListener::accept_one() {
  Accepted a;
  sockaddr_in peer{};
  socklen_t len = sizeof peer;
  a.fd = ::accept4(fd_, reinterpret_cast<sockaddr*>(&peer), &len, SOCK_CLOEXEC);
  if (a.fd < 0) return a;
  a.local = peer.sin_family == AF_INET && ntohl(peer.sin_addr.s_addr) == INADDR_LOOPBACK;
  std::string head;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
  while (head.find("\r\n\r\n") == std::string::npos && head.size() < 16384) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()).count();
    pollfd p{a.fd, POLLIN, 0};
    if (left <= 0 || ::poll(&p, 1, static_cast<int>(left)) <= 0) break;
    char buf[4096];
    const ssize_t n = ::read(a.fd, buf, sizeof buf);
    if (n <= 0) break;
    head.append(buf, static_cast<std::size_t>(n));
  }
  a.request = parse_http_request(head);
  if (!a.request) {
    http_respond(a.fd, 400, "text/plain", "bad request\n");
    a.fd = -1;
  }
  return a;
}

void http_respond(int fd, int status, const std::string& type, std::string_view body) {
  const std::string head =
      "HTTP/1.1 " + std::to_string(status) + " " + reason(status) + "\r\nContent-Type: " + type +
      "\r\nContent-Length: " + std::to_string(body.size()) +
      "\r\nCache-Control: no-store\r\nX-Content-Type-Options: nosniff\r\nConnection: close\r\n\r\n";
  for (std::string_view part : {std::string_view(head), body}) {
    while (!part.empty()) {
      const ssize_t n = ::send(fd, part.data(), part.size(), MSG_NOSIGNAL);
      if (n <= 0) break;
      part.remove_prefix(static_cast<std::size_t>(n));
    }
  }
  ::close(fd);
}

}  // namespace selfsim::interp
