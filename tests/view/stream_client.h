#pragma once
/// \file
/// A client of prt view's frame stream (GET /stream, src/view/frame_stream.h) over a socket of
/// the test's own: it decodes the chunked response and its records (src/view/stream_record.h)
/// as the page does, and can stop reading, to play a page that stalls.

#include <cstdint>
#include <string>

namespace prt::test {

struct StreamRecord {
  std::string kind;  ///< "PRTF", "PRTE", "PRTK"; "" when none came (closed, or the time ran out)
  std::uint32_t frame = 0, input = 0, width = 0, height = 0, draw_us = 0, flags = 0;
  std::string body;  ///< RGBA for a frame, the text of an error
  /// The frame's RGB bytes, as /frame sends them.
  std::string Rgb() const;
};

class StreamClient {
 public:
  /// GET /stream?stream=NAME&input=INPUT&QUERY on 127.0.0.1:port, with the page's X-Prt-Stream
  /// header; reads the reply's head.
  StreamClient(int port, const std::string& name, const std::string& query, std::uint64_t input);
  ~StreamClient();
  StreamClient(const StreamClient&) = delete;
  StreamClient& operator=(const StreamClient&) = delete;

  int status() const { return status_; }
  const std::string& head() const { return head_; }
  /// The next record, waiting up to `seconds`; kind "" when none came. Keep-alives are returned.
  StreamRecord Next(double seconds = 30.0);
  /// True once the stream's response has ended (its last chunk read) or the connection closed.
  bool Ended() const { return ended_; }
  int fd() const { return fd_; }

 private:
  /// Reads from the socket into raw_ (up to the deadline); false when nothing more will come.
  bool Fill(double seconds);
  /// Moves whole chunks of raw_ into data_.
  void Dechunk();

  int fd_ = -1;
  int status_ = 0;
  std::string head_, raw_, data_;
  bool ended_ = false;
};

/// POST /input?stream=NAME&PARAMS with the page's Origin and X-Prt-Stream header: the reply's status.
int PostInput(int port, const std::string& name, const std::string& params);

}  // namespace prt::test
