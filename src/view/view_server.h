#pragma once
/// \file
/// The web server of `prt view` (cpp-httplib, Debian's libcpp-httplib): the page, and what the
/// page asks of the scene behind it (ViewBackend). Routes:
///
///   GET  /, /view.js      the embedded page (view/page.h); any other path is 404
///   GET  /state           the run as JSON (ViewBackend::StateJson): limits, defaults, progress
///   GET  /frame?QUERY     one frame (view/frame_request.h) as raw RGB bytes, row by row from the
///                         top; its size and the time it took to draw in the headers
///                         X-Prt-Size (WxH) and X-Prt-Draw-Ms
///   GET  /frame.png?QUERY the same frame as a PNG file, to save
///   GET  /stream?stream=NAME&input=N&QUERY   (with the header X-Prt-Stream: 1, which only the
///                         page itself can send: 403 without) the page's frames, pushed as they are drawn on one
///                         response (view/frame_stream.h; records: view/stream_record.h),
///                         starting with QUERY as input N; at most kMaxStreams open at once (400
///                         beyond); a stream opened again under its NAME replaces the old one
///   POST /input?stream=NAME&shown=F[&input=N&QUERY]   (X-Prt-Stream: 1 too) the page has shown
///                         frame F; it now wants QUERY (input N): 204, 404 for a stream not open
///   GET  /command?QUERY   the `prt render` command line that draws the same frame
///   POST /compute?basis=B&mode=M   starts computing that transport (202), progress in /state
///   POST /reference?mode=M&env=I   starts measuring prt reference's radiance for them (202)
///   GET  /error?QUERY     the frame's setting's error against that reference, as JSON (409
///                         until it is measured)
///
/// Every request passes view/request_guard.h first (its Host, Origin, token and framing: 403,
/// 400, 411, 413). A bad query is 400 with the reason, a frame of a transport not computed yet
/// 409, a frame asked for while four wait 503 (view/draw_queue.h), any other method 405, and the
/// server goes on. Each request must arrive whole within 5 s of its first byte (408 and closed:
/// view/deadline_server.h) and each write completes within 5 s, so a client that stalls,
/// trickles or disappears holds its connection's thread for seconds; threads are made as
/// connections come (view/growing_pool.h), so such clients never keep the page waiting. The
/// backend draws one frame at a time, the page's frames first, and a frame's bytes are sent after
/// its turn is left.

#include <atomic>
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/image.h"
#include "view/frame_request.h"

namespace prt {

/// A frame the transport of which is still being computed (409).
struct NotReady : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The scene behind the page. Every call may come from any server thread.
class ViewBackend {
 public:
  virtual ~ViewBackend() = default;
  virtual const ViewLimits& Limits() const = 0;
  /// The first frame: the command line's options.
  virtual const FrameRequest& Defaults() const = 0;
  virtual std::string StateJson() const = 0;
  /// Draws `request`; throws NotReady while its transport is being computed, Error for one the
  /// run cannot draw. `draw_ms` gets the time the drawing took.
  virtual Image8 Frame(const FrameRequest& request, double* draw_ms) = 0;
  /// Starts computing `basis`'s transport in `mode` in the background, if not done or started.
  virtual void Compute(const std::string& basis, const std::string& mode) = 0;
  /// Starts measuring the reference (precompute/reference.h) of `request`'s mode and environment
  /// in the background, if not done or started.
  virtual void MeasureReference(const FrameRequest& request) = 0;
  /// {"error": E, "reference_error": R, ...}: the relative RMS error of `request`'s per-vertex
  /// radiance (its basis, mode, lmax and environment, the light unturned) against the measured
  /// reference, and the reference's own; throws NotReady until that reference is measured.
  virtual std::string ErrorJson(const FrameRequest& request) = 0;
  /// The `prt render` command line that draws `request` as its frame 0.
  virtual std::string Command(const FrameRequest& request) const = 0;
};

/// The bytes the frames asked for may hold until sent: five of the largest raw frames (4096^2
/// RGB, 48 MiB).
inline constexpr std::size_t kHeldFrameBytes = std::size_t(256) << 20;

/// Streams open at once: a page keeps one; each holds a server thread while it lasts.
inline constexpr std::size_t kMaxStreams = 8;

class ViewServer {
 public:
  /// Binds `bind`:`port` (0: any free port); throws Error when it cannot. The frames asked for
  /// by /frame and /frame.png hold at most `held_frame_bytes` until sent (view/draw_queue.h).
  ViewServer(ViewBackend& backend, const std::string& bind, int port, std::size_t held_frame_bytes = kHeldFrameBytes);
  ~ViewServer();
  ViewServer(const ViewServer&) = delete;
  ViewServer& operator=(const ViewServer&) = delete;

  int port() const { return port_; }
  /// http://ADDRESS:PORT/ (an IPv6 address in brackets; a wildcard bind's loopback address).
  std::string Address() const;
  /// The Host values served (view/request_guard.h): for a wildcard bind, this machine's names.
  const std::vector<std::string>& Hosts() const;
  /// The run's token, which every request but the page's files and /state carries (the page has
  /// it from the page served at /).
  const std::string& Token() const;
  /// Serves until Stop() (at once when Stop came first).
  void Serve();
  /// Ends Serve, from any thread, whether or not Serve has started listening yet.
  void Stop();

 private:
  class Streams;
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::string bind_;
  int port_ = 0;
  std::atomic<bool> serving_{false}, stopping_{false};
};

}  // namespace prt
