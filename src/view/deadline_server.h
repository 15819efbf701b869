#pragma once
/// \file
/// The HTTP library's server (cpp-httplib 0.11), its connections read by prt's own stream so
/// that each request must arrive whole within a deadline. The library's read timeout applies to
/// each read and starts again with every byte: a client that sends one header line every few
/// seconds holds its connection, and a thread, for as long as it goes on, and 40 such clients
/// kept `prt view`'s page from its own state. Here the line, headers and body of a request must
/// all arrive within `request_deadline` of its first byte, and be at most kMaxRequestBytes; a
/// connection past either gets 408 (431) and is closed. Each write of a response must be sent
/// within the write timeout plus its size at kMinWriteRate, and a response begun is sent whole even
/// when the server stops meanwhile. Between requests a connection waits up to the library's
/// keep-alive timeout for the next one. Waits for a request are sliced so that a stopped server's
/// idle connections end within kStopSlice.
///
/// Everything else (parsing, routing, responses) is the library's: this replaces only its
/// per-connection loop, through the hook the library gives for it (process_and_close_socket,
/// which its TLS server overrides the same way).

#include <chrono>
#include <cstddef>
#include <memory>

#include <httplib.h>

namespace prt {

class DeadlineServer : public httplib::Server {
 public:
  explicit DeadlineServer(std::chrono::milliseconds request_deadline) : request_deadline_(request_deadline) {}

  /// True on a thread serving a request that did not arrive whole within its deadline: for the
  /// error handler, which answers it with 408.
  static bool RequestExpired();
  /// True on a thread serving a request of more than kMaxRequestBytes (431 and closed).
  static bool RequestTooLarge();
  /// Called by a handler of this thread's request: its connection is closed after the answer
  /// (the bytes after a request refused for its framing cannot be trusted to start the next).
  static void CloseAfterResponse();
  /// Called by a handler of this thread's request: `held` is kept until its answer has been
  /// written (a frame's byte reservation, view/draw_queue.h), then released.
  static void HoldUntilSent(std::shared_ptr<void> held);

  /// How often a wait looks whether the server has been stopped.
  static constexpr std::chrono::milliseconds kStopSlice{50};
  /// A request's line, headers and body at most: the deadline bounds a request's time, this its
  /// memory (the library keeps every header line it reads).
  static constexpr std::size_t kMaxRequestBytes = 64 * 1024;
  /// Bytes a second a response's write goes at least, after the write timeout: a 48 MiB frame
  /// may take 5 s + 48 s, a client reading a few bytes now and then is cut off.
  static constexpr double kMinWriteRate = 1024.0 * 1024.0;

 private:
  bool process_and_close_socket(socket_t sock) override;

  const std::chrono::milliseconds request_deadline_;
};

}  // namespace prt
