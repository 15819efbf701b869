#include "tests/view/http_client.h"

#include <chrono>
#include <cstdlib>
#include <map>
#include <mutex>
#include <string>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <doctest/doctest.h>

namespace prt::test {

std::string HttpReply::Header(const std::string& name) const {
  const std::string key = "\r\n" + name + ": ";
  const std::size_t at = head.find(key);
  if (at == std::string::npos) return "";
  const std::size_t start = at + key.size();
  return head.substr(start, head.find("\r\n", start) - start);
}

namespace {

/// A socket connected to 127.0.0.1:port, or -1.
int TryConnect(int port) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(static_cast<std::uint16_t>(port));
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (fd >= 0 && ::connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0) return fd;
  if (fd >= 0) ::close(fd);
  return -1;
}

}  // namespace

int Connect(int port) {
  const int fd = TryConnect(port);
  REQUIRE(fd >= 0);
  return fd;
}

bool StillOpen(int fd) {
  pollfd p{fd, POLLIN, 0};
  return ::poll(&p, 1, 0) == 0;
}

HttpReply SendRaw(int port, const std::string& raw) {
  HttpReply reply;
  const int fd = TryConnect(port);
  if (fd < 0) return reply;
  for (std::size_t sent = 0; sent < raw.size();) {
    const ssize_t n = ::send(fd, raw.data() + sent, raw.size() - sent, MSG_NOSIGNAL);
    if (n <= 0) break;
    sent += static_cast<std::size_t>(n);
  }
  std::string all;
  char buffer[65536];
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (std::chrono::steady_clock::now() < deadline) {
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, 1000) <= 0) continue;
    const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
    if (n <= 0) break;
    all.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fd);
  const std::size_t end = all.find("\r\n\r\n");
  if (all.rfind("HTTP/1.1 ", 0) != 0 || end == std::string::npos) return reply;
  reply.status = std::atoi(all.c_str() + 9);
  reply.head = all.substr(0, end);
  reply.body = all.substr(end + 4);
  return reply;
}

namespace {
std::mutex token_mutex;
std::map<int, std::string> tokens;  // by port
}  // namespace

void UseToken(int port, const std::string& token) {
  std::lock_guard<std::mutex> lock(token_mutex);
  tokens[port] = token;
}

std::string TokenHeader(int port) {
  std::lock_guard<std::mutex> lock(token_mutex);
  const auto it = tokens.find(port);
  return it == tokens.end() ? "" : "X-Prt-Token: " + it->second + "\r\n";
}

std::string FetchToken(int port) {
  const HttpReply page = Request(port, "/");
  const std::string tag = "<meta name=\"prt-token\" content=\"";
  const std::size_t at = page.body.find(tag);
  REQUIRE_MESSAGE(at != std::string::npos, "the page at / has no token (status " << page.status << ")");
  const std::size_t begin = at + tag.size(), end = page.body.find('"', begin);
  REQUIRE(end != std::string::npos);
  const std::string token = page.body.substr(begin, end - begin);
  UseToken(port, token);
  return token;
}

HttpReply Request(int port, const std::string& target, const std::string& method, const std::string& extra,
                  const std::string& body) {
  const std::string token = extra.find("X-Prt-Token:") == std::string::npos ? TokenHeader(port) : "";
  std::string raw = method + " " + target + " HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) + "\r\n" + token +
                    extra + "Connection: close\r\n";
  if (!body.empty() || method != "GET") raw += "Content-Length: " + std::to_string(body.size()) + "\r\n";
  return SendRaw(port, raw + "\r\n" + body);
}

}  // namespace prt::test
