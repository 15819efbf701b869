#include "view/deadline_server.h"

#include <algorithm>
#include <atomic>
#include <array>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

namespace prt {
namespace {

using Clock = std::chrono::steady_clock;


/// The numeric address and port of `sock`'s `peer` (getpeername) or own end (getsockname).
void Address(int sock, bool peer, std::string& ip, int& port) {
  sockaddr_storage addr{};
  socklen_t len = sizeof addr;
  const int got = peer ? ::getpeername(sock, reinterpret_cast<sockaddr*>(&addr), &len)
                       : ::getsockname(sock, reinterpret_cast<sockaddr*>(&addr), &len);
  std::array<char, NI_MAXHOST> host{};
  std::array<char, NI_MAXSERV> serv{};
  if (got != 0 || ::getnameinfo(reinterpret_cast<sockaddr*>(&addr), len, host.data(), host.size(), serv.data(),
                                serv.size(), NI_NUMERICHOST | NI_NUMERICSERV) != 0)
    return;
  ip = host.data();
  port = std::atoi(serv.data());
}

/// A connection's socket as the library reads and writes it: reads buffered (the library reads
/// a request's line and headers a byte at a time), each read bounded by the read timeout, by the
/// current request's deadline and by its bytes (kMaxRequestBytes); each write sent whole within
/// the write timeout plus its size at kMinWriteRate, or failed.
class DeadlineStream final : public httplib::Stream {
 public:
  DeadlineStream(int sock, Clock::duration read_timeout, Clock::duration write_timeout,
                 const std::atomic<socket_t>& server_socket)
      : sock_(sock), read_timeout_(read_timeout), write_timeout_(write_timeout), server_socket_(server_socket) {}

  /// A request begins: its reads must be done by `deadline`.
  void Begin(Clock::time_point deadline) {
    deadline_ = deadline;
    expired_ = overflowed_ = false;
    read_ = 0;
  }
  bool Expired() const { return expired_; }
  bool Overflowed() const { return overflowed_; }
  /// The connection ends after this request's answer.
  void CloseAfter() const { close_ = true; }
  /// `held` is kept until this request's answer has been written (or failed).
  void Hold(std::shared_ptr<void> held) const { held_.push_back(std::move(held)); }
  void ReleaseHeld() const { held_.clear(); }
  bool Closing() const { return close_ || expired_ || overflowed_; }
  bool Buffered() const { return begin_ < end_; }

  /// Waits until the socket has `events` (POLLIN, POLLOUT) or `until`, or, when `stoppable`, the
  /// server stops: true when it has them.
  bool Wait(short events, Clock::time_point until, bool stoppable) const {
    for (;;) {
      if (stoppable && server_socket_ == INVALID_SOCKET) return false;
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - Clock::now());
      if (left.count() < 0) return false;
      pollfd p{sock_, events, 0};
      const int n = ::poll(&p, 1, static_cast<int>(std::min(left, DeadlineServer::kStopSlice).count()));
      if (n > 0) return (p.revents & (events | POLLHUP | POLLERR)) != 0;
      if (n < 0 && errno != EINTR) return false;
    }
  }

  bool is_readable() const override {
    if (Buffered()) return true;
    const Clock::time_point until = std::min(Clock::now() + read_timeout_, deadline_);
    if (Wait(POLLIN, until, true)) return true;
    if (Clock::now() >= deadline_) expired_ = true;
    return false;
  }
  // A response begun is sent whole, stopped server or not (a client must never take a cut-off
  // body for the whole): its writes are bounded by their own deadlines, not by Stop.
  bool is_writable() const override { return Wait(POLLOUT, Clock::now() + write_timeout_, false); }

  ssize_t read(char* ptr, size_t size) override {
    if (read_ >= DeadlineServer::kMaxRequestBytes) {
      overflowed_ = true;
      return -1;
    }
    size = std::min(size, DeadlineServer::kMaxRequestBytes - read_);
    if (!Buffered()) {
      if (!is_readable()) return -1;
      const ssize_t n = Receive(buffer_.data(), buffer_.size());
      if (n <= 0) return n;
      begin_ = 0;
      end_ = static_cast<std::size_t>(n);
    }
    const std::size_t n = std::min(size, end_ - begin_);
    std::memcpy(ptr, buffer_.data() + begin_, n);
    begin_ += n;
    read_ += n;
    return static_cast<ssize_t>(n);
  }
  /// Sends all of `ptr` by its deadline, or fails: a client that reads a little now and then
  /// cannot keep a response's thread (and the frame it holds) for ever.
  ssize_t write(const char* ptr, size_t size) override {
    const auto rate = std::chrono::duration<double>(double(size) / DeadlineServer::kMinWriteRate);
    const Clock::time_point until = Clock::now() + write_timeout_ + std::chrono::duration_cast<Clock::duration>(rate);
    std::size_t sent = 0;
    while (sent < size) {
      if (!Wait(POLLOUT, until, false)) return -1;
      // Not blocking: the library set a send timeout on the socket, which a blocking send of a
      // large buffer would wait out on each call.
      const ssize_t n = ::send(sock_, ptr + sent, size - sent, MSG_NOSIGNAL | MSG_DONTWAIT);
      if (n < 0 && errno != EINTR && errno != EAGAIN && errno != EWOULDBLOCK) return -1;
      if (n > 0) sent += static_cast<std::size_t>(n);
    }
    return static_cast<ssize_t>(size);
  }
  void get_remote_ip_and_port(std::string& ip, int& port) const override { Address(sock_, true, ip, port); }
  void get_local_ip_and_port(std::string& ip, int& port) const override { Address(sock_, false, ip, port); }
  socket_t socket() const override { return sock_; }

 private:
  ssize_t Receive(char* into, std::size_t size) const {
    for (;;) {
      const ssize_t n = ::recv(sock_, into, size, 0);
      if (n >= 0 || errno != EINTR) return n;
    }
  }

  const int sock_;
  const Clock::duration read_timeout_, write_timeout_;
  const std::atomic<socket_t>& server_socket_;
  Clock::time_point deadline_ = Clock::time_point::max();
  mutable bool expired_ = false, close_ = false;
  mutable std::vector<std::shared_ptr<void>> held_;
  bool overflowed_ = false;
  std::size_t read_ = 0;  ///< bytes of the current request read
  std::array<char, 4096> buffer_{};
  std::size_t begin_ = 0, end_ = 0;
};

/// An answer written by hand, to a request cut off in its request line (the library writes none).
std::string Answer(const std::string& status, const std::string& text) {
  return "HTTP/1.1 " + status + "\r\nConnection: close\r\nContent-Type: text/plain; charset=utf-8\r\nContent-Length: " +
         std::to_string(text.size() + 1) + "\r\n\r\n" + text + "\n";
}

/// The stream of the connection this thread serves, if any.
thread_local const DeadlineStream* current_stream = nullptr;

}  // namespace

bool DeadlineServer::RequestExpired() { return current_stream != nullptr && current_stream->Expired(); }

bool DeadlineServer::RequestTooLarge() { return current_stream != nullptr && current_stream->Overflowed(); }

void DeadlineServer::CloseAfterResponse() {
  if (current_stream != nullptr) current_stream->CloseAfter();
}

void DeadlineServer::HoldUntilSent(std::shared_ptr<void> held) {
  if (current_stream != nullptr) current_stream->Hold(std::move(held));
}

bool DeadlineServer::process_and_close_socket(socket_t sock) {
  const auto seconds = [](time_t s, time_t us) {
    return std::chrono::duration_cast<Clock::duration>(std::chrono::seconds(s) + std::chrono::microseconds(us));
  };
  DeadlineStream stream(sock, seconds(read_timeout_sec_, read_timeout_usec_),
                        seconds(write_timeout_sec_, write_timeout_usec_), svr_sock_);
  bool ok = false;
  for (std::size_t count = keep_alive_max_count_; count > 0; --count) {
    // The next request: bytes already read, or its first byte within the keep-alive timeout.
    if (!stream.Buffered() &&
        !stream.Wait(POLLIN, Clock::now() + std::chrono::seconds(keep_alive_timeout_sec_), true))
      break;
    stream.Begin(Clock::now() + request_deadline_);
    bool closed = false;
    // The library reads the request through `stream`; past its deadline a read fails, and the
    // error handler sees RequestExpired().
    struct Current {  // this thread's stream, for the handlers, while the request is served
      explicit Current(const DeadlineStream* s) { current_stream = s; }
      ~Current() { current_stream = nullptr; }
    } current(&stream);
    ok = process_request(stream, count == 1, closed, nullptr);
    stream.ReleaseHeld();
    // Cut off in its request line, a request gets no answer from the library: it gets this one.
    if (!ok && (stream.Expired() || stream.Overflowed())) {
      const std::string answer = stream.Expired()
                                     ? Answer("408 Request Timeout", "request: not whole within its deadline (closed)")
                                     : Answer("431 Request Header Fields Too Large", "request: over 64 KiB (closed)");
      stream.write(answer.data(), answer.size());
    }
    if (!ok || closed || stream.Closing()) break;
  }
  ::shutdown(sock, SHUT_RDWR);
  ::close(sock);
  return ok;
}

}  // namespace prt
