#include "tests/view/stream_client.h"

#include <chrono>
#include <cstdlib>

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <doctest/doctest.h>

#include "tests/view/http_client.h"

namespace prt::test {
namespace {

std::uint32_t Field(const std::string& s, std::size_t at) {
  std::uint32_t v = 0;
  for (int b = 3; b >= 0; --b) v = (v << 8) | static_cast<unsigned char>(s[at + b]);
  return v;
}

}  // namespace

std::string StreamRecord::Rgb() const {
  std::string rgb;
  rgb.reserve(body.size() / 4 * 3);
  for (std::size_t i = 0; i + 3 < body.size(); i += 4) rgb.append(body, i, 3);
  return rgb;
}

StreamClient::StreamClient(int port, const std::string& name, const std::string& query, std::uint64_t input) {
  fd_ = Connect(port);
  const std::string raw = "GET /stream?stream=" + name + "&input=" + std::to_string(input) + (query.empty() ? "" : "&") +
                          query + " HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) + "\r\nX-Prt-Stream: 1\r\n" + TokenHeader(port) + "\r\n";
  REQUIRE(::send(fd_, raw.data(), raw.size(), MSG_NOSIGNAL) == static_cast<ssize_t>(raw.size()));
  while (raw_.find("\r\n\r\n") == std::string::npos)
    if (!Fill(30.0)) break;
  const std::size_t end = raw_.find("\r\n\r\n");
  if (raw_.rfind("HTTP/1.1 ", 0) != 0 || end == std::string::npos) return;
  status_ = std::atoi(raw_.c_str() + 9);
  head_ = raw_.substr(0, end);
  raw_.erase(0, end + 4);
  if (head_.find("Transfer-Encoding: chunked") == std::string::npos) {
    data_ = raw_;  // an error's body
    ended_ = true;
  }
}

StreamClient::~StreamClient() {
  if (fd_ >= 0) ::close(fd_);
}

bool StreamClient::Fill(double seconds) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  char buffer[1 << 16];
  while (std::chrono::steady_clock::now() < deadline) {
    pollfd p{fd_, POLLIN, 0};
    if (::poll(&p, 1, 50) <= 0) continue;
    const ssize_t n = ::recv(fd_, buffer, sizeof buffer, 0);
    if (n <= 0) {
      ended_ = true;
      return false;
    }
    raw_.append(buffer, static_cast<std::size_t>(n));
    return true;
  }
  return false;
}

void StreamClient::Dechunk() {
  for (;;) {
    const std::size_t line = raw_.find("\r\n");
    if (line == std::string::npos) return;
    const std::size_t size = std::strtoul(raw_.substr(0, line).c_str(), nullptr, 16);
    if (size == 0) {  // the last chunk: the response ended
      ended_ = true;
      raw_.clear();
      return;
    }
    if (raw_.size() < line + 2 + size + 2) return;
    data_.append(raw_, line + 2, size);
    raw_.erase(0, line + 2 + size + 2);
  }
}

StreamRecord StreamClient::Next(double seconds) {
  StreamRecord r;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  for (;;) {
    Dechunk();
    if (data_.size() >= 32) {
      const std::string kind = data_.substr(0, 4);
      const std::uint32_t width = Field(data_, 12), height = Field(data_, 16);
      const std::size_t body = kind == "PRTF" ? std::size_t(4) * width * height : kind == "PRTE" ? Field(data_, 12) : 0;
      if (data_.size() >= 32 + body) {
        r.kind = kind;
        r.frame = Field(data_, 4);
        r.input = Field(data_, 8);
        r.width = width;
        r.height = height;
        r.draw_us = Field(data_, 20);
        r.flags = Field(data_, 24);
        r.body = data_.substr(32, body);
        data_.erase(0, 32 + body);
        return r;
      }
    }
    const double left = std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
    if (ended_ || left <= 0 || !Fill(left)) return r;
  }
}

int PostInput(int port, const std::string& name, const std::string& params) {
  return Request(port, "/input?stream=" + name + (params.empty() ? "" : "&") + params, "POST",
                 "Origin: http://127.0.0.1:" + std::to_string(port) + "\r\nX-Prt-Stream: 1\r\n")
      .status;
}

}  // namespace prt::test
