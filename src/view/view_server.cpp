#include "view/view_server.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <exception>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>

#include <httplib.h>
#include <sys/socket.h>

#include "core/error.h"
#include "core/text.h"
#include "io/png_io.h"
#include "view/frame_stream.h"
#include "view/page.h"
#include "view/request_guard.h"
#include "view/stream_record.h"

namespace prt {
namespace {

/// Seconds a connection may take to send its request or to read a response before it is
/// dropped: a stalled client holds one pool thread at most this long.
constexpr int kTimeoutSeconds = 5;
/// The largest request body accepted: the page sends none.
constexpr std::size_t kMaxBody = 1024;
/// Threads serving connections: a page keeps one or two busy, so 32 leave room for 30 stalled
/// clients before another waits for a timeout.
constexpr std::size_t kPoolThreads = 32;

void Text(httplib::Response& res, int status, const std::string& text) {
  res.status = status;
  res.set_content(text + "\n", "text/plain; charset=utf-8");
}

/// A request refused whatever its parameters (403).
struct Refused : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::vector<std::pair<std::string, std::string>> Query(const httplib::Request& req) {
  return {req.params.begin(), req.params.end()};
}

/// The header the page puts on its stream requests. A page of another origin cannot send it
/// without asking first (a CORS preflight, which OPTIONS' 405 refuses), nor can an <img> or a
/// form: only prt's own page opens streams and sends their input, even from the same site.
constexpr const char* kStreamHeader = "X-Prt-Stream";

/// Refuses a stream request without kStreamHeader (403).
void RequireStreamHeader(const httplib::Request& req) {
  if (req.get_header_value(kStreamHeader) != "1")
    throw Refused(std::string("refused: ") + kStreamHeader + ": 1 missing (only prt's own page opens a stream)");
}

/// A stream's name: the page's own random one, 16 to 64 hexadecimal digits.
std::string StreamName(const httplib::Request& req) {
  const std::string id = req.get_param_value("stream");
  const bool hex = std::all_of(id.begin(), id.end(), [](char c) { return std::isxdigit(static_cast<unsigned char>(c)); });
  if (id.size() < 16 || id.size() > 64 || !hex)
    throw Error("stream=" + id + ": refused (expected the page's stream name, 16 to 64 hexadecimal digits)");
  return id;
}

/// A count the page sends (input=, shown=): a whole number 0..2^53.
std::uint64_t Count(const std::string& name, const std::string& value) {
  const std::optional<double> x = ParseNumber(value);
  if (!x || *x < 0 || *x > 9007199254740992.0 || *x != std::floor(*x))
    throw Error(name + "=" + value + ": refused (expected a whole number)");
  return static_cast<std::uint64_t>(*x);
}

/// The frame query of a stream request: its parameters but stream=, input= and shown=.
std::vector<std::pair<std::string, std::string>> FrameParams(const httplib::Request& req) {
  std::vector<std::pair<std::string, std::string>> query;
  for (const auto& [name, value] : req.params)
    if (name != "stream" && name != "input" && name != "shown") query.emplace_back(name, value);
  return query;
}

}  // namespace

/// The open streams by name. A page that reconnects under the same name replaces its old stream
/// (stopped); Close forgets a stream when its response ends, unless it was replaced.
class ViewServer::Streams {
 public:
  void Open(const std::string& name, const std::shared_ptr<FrameStream>& stream) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (closed_) throw Error("the server is stopping");
    auto it = open_.find(name);
    if (it != open_.end()) {
      it->second->Stop();
      it->second = stream;
      return;
    }
    if (open_.size() >= kMaxStreams)
      throw Error("stream: refused (" + std::to_string(kMaxStreams) + " streams are open, the most served at once)");
    open_.emplace(name, stream);
  }
  std::shared_ptr<FrameStream> Find(const std::string& name) const {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = open_.find(name);
    return it == open_.end() ? nullptr : it->second;
  }
  void Close(const std::string& name, const FrameStream* stream) {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = open_.find(name);
    if (it != open_.end() && it->second.get() == stream) open_.erase(it);
  }
  /// True once StopAll has been called: the server is stopping.
  bool Closed() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return closed_;
  }
  /// Stops every stream, and those opened later at once.
  void StopAll() {
    std::lock_guard<std::mutex> lock(mutex_);
    closed_ = true;
    for (auto& [name, stream] : open_) stream->Stop();
  }

 private:
  mutable std::mutex mutex_;
  std::map<std::string, std::shared_ptr<FrameStream>> open_;
  bool closed_ = false;
};

struct ViewServer::Impl {
  httplib::Server server;
  std::vector<std::string> hosts;
  Streams streams;
};

ViewServer::ViewServer(ViewBackend& backend, const std::string& bind, int port)
    : impl_(std::make_unique<Impl>()), bind_(bind) {
  httplib::Server& s = impl_->server;
  s.set_read_timeout(kTimeoutSeconds, 0);
  s.set_write_timeout(kTimeoutSeconds, 0);
  s.set_payload_max_length(kMaxBody);
  s.set_keep_alive_max_count(10000);  // the page asks for frame after frame on one connection
  // Each connection holds a pool thread while it is read or written: enough of them that clients
  // which stall (each dropped after its timeout) leave threads for the others.
  s.new_task_queue = [] { return new httplib::ThreadPool(kPoolThreads); };
  // The library's default, SO_REUSEPORT, would let a second server share the port and take half
  // its connections: SO_REUSEADDR alone lets a restart take the port of one just ended, no more.
  s.set_socket_options([](int sock) {
    int yes = 1;
    ::setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  });  // the page asks for frame after frame on one connection
  s.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    const std::string why = RefusedRequest(req.method, req.get_header_value("Host"), req.get_header_value("Origin"),
                                           req.get_header_value("Sec-Fetch-Site"), impl_->hosts);
    if (why.empty()) return httplib::Server::HandlerResponse::Unhandled;
    Text(res, 403, "refused: " + why);
    return httplib::Server::HandlerResponse::Handled;
  });
  // Anything a handler throws is the request's fault or the scene's: an answer, never an end.
  const auto guarded = [](auto handler) {
    return [handler](const httplib::Request& req, httplib::Response& res) {
      try {
        handler(req, res);
      } catch (const Refused& e) {
        Text(res, 403, e.what());
      } catch (const NotReady& e) {
        Text(res, 409, e.what());
      } catch (const Error& e) {
        Text(res, 400, e.what());
      } catch (const std::exception& e) {
        Text(res, 500, std::string("internal error: ") + e.what());
      }
    };
  };
  s.Get(R"(/|/[A-Za-z0-9_.-]+\.(html|js))", guarded([](const httplib::Request& req, httplib::Response& res) {
          const std::optional<PageFile> file = FindPageFile(req.path);
          if (!file) return Text(res, 404, "not found: " + req.path);
          res.set_content(std::string(file->body), file->type);
          res.set_header("Cache-Control", "no-store");
        }));
  s.Get("/state", guarded([&backend](const httplib::Request&, httplib::Response& res) {
          res.set_content(backend.StateJson(), "application/json");
          res.set_header("Cache-Control", "no-store");
        }));
  const auto frame = [&backend](const httplib::Request& req, bool png, httplib::Response& res) {
    const FrameRequest request = ParseFrameRequest(Query(req), backend.Defaults(), backend.Limits());
    double ms = 0.0;
    const Image8 image = backend.Frame(request, &ms);
    res.set_header("X-Prt-Size", std::to_string(image.width) + "x" + std::to_string(image.height));
    res.set_header("X-Prt-Draw-Ms", std::to_string(ms));
    res.set_header("Cache-Control", "no-store");
    if (png) {
      res.set_header("Content-Disposition", "attachment; filename=\"prt-view.png\"");
      res.set_content(EncodePng(image), "image/png");
    } else {
      res.set_content(std::string(image.rgb.begin(), image.rgb.end()), "application/octet-stream");
    }
  };
  s.Get("/frame", guarded([frame](const httplib::Request& req, httplib::Response& res) { frame(req, false, res); }));
  s.Get("/frame.png", guarded([frame](const httplib::Request& req, httplib::Response& res) { frame(req, true, res); }));
  // The stream of frames (view/frame_stream.h): each draw and send on this connection's thread,
  // every write bounded by the write timeout, so a page that stops reading frees it.
  s.Get("/stream", guarded([this, &backend](const httplib::Request& req, httplib::Response& res) {
          RequireStreamHeader(req);
          const std::string name = StreamName(req);
          const std::uint64_t input = req.has_param("input") ? Count("input", req.get_param_value("input")) : 0;
          auto stream = std::make_shared<FrameStream>(
              ParseFrameRequest(FrameParams(req), backend.Defaults(), backend.Limits()), input);
          impl_->streams.Open(name, stream);
          res.set_header("Cache-Control", "no-store");
          res.set_chunked_content_provider(
              "application/octet-stream",
              [this, stream, &backend](std::size_t, httplib::DataSink& sink) {
                // Nothing may escape to the library (it would end the run): what cannot be sent
                // ends this stream, and the page opens another.
                try {
                  FrameStream::Job job;
                  switch (stream->Next(job)) {
                    case FrameStream::Step::kStopped:
                      // The server stops: the connection is closed at once (a finished response
                      // would keep it for the next request). The page opened another stream, or
                      // went silent: the response ends whole, its last chunk sent, so that the
                      // browser sees an end, not a broken download.
                      if (this->impl_->streams.Closed()) return false;
                      sink.done();
                      return true;
                    case FrameStream::Step::kKeepAlive: {
                      const std::string record = KeepAliveRecord();
                      return sink.write(record.data(), record.size());
                    }
                    case FrameStream::Step::kDraw:
                      break;
                  }
                  std::string record;
                  try {
                    double ms = 0.0;
                    const Image8 image = backend.Frame(job.request, &ms);
                    record = FrameRecord(image, job.frame, job.input, ms, !job.request.interactive);
                  } catch (const std::exception& e) {  // NotReady, Error: the page shows why
                    record = ErrorRecord(job.frame, job.input, e.what());
                  }
                  return sink.write(record.data(), record.size());
                } catch (...) {
                  return false;
                }
              },
              [this, name, raw = stream.get()](bool) { impl_->streams.Close(name, raw); });
        }));
  s.Post("/input", guarded([this, &backend](const httplib::Request& req, httplib::Response& res) {
           RequireStreamHeader(req);
           const std::shared_ptr<FrameStream> stream = impl_->streams.Find(StreamName(req));
           if (!stream) return Text(res, 404, "stream: not open (it ended: the page opens another)");
           if (req.has_param("shown")) stream->Shown(Count("shown", req.get_param_value("shown")));
           const std::vector<std::pair<std::string, std::string>> frame = FrameParams(req);
           if (req.has_param("input")) {
             const std::uint64_t input = Count("input", req.get_param_value("input"));
             stream->Want(ParseFrameRequest(frame, backend.Defaults(), backend.Limits()), input);
           } else if (!frame.empty()) {
             throw Error(frame.front().first + ": a frame parameter without input= (expected input=N with them)");
           }
           res.status = 204;
         }));
  s.Get("/command", guarded([&backend](const httplib::Request& req, httplib::Response& res) {
          const FrameRequest request = ParseFrameRequest(Query(req), backend.Defaults(), backend.Limits());
          res.set_content(backend.Command(request) + "\n", "text/plain; charset=utf-8");
        }));
  s.Post("/compute", guarded([&backend](const httplib::Request& req, httplib::Response& res) {
           FrameRequest request = backend.Defaults();
           std::vector<std::pair<std::string, std::string>> query;
           for (const auto& [name, value] : req.params) {
             if (name != "basis" && name != "mode") throw Error(name + ": unknown parameter (expected basis, mode)");
             query.emplace_back(name, value);
           }
           request = ParseFrameRequest(query, request, backend.Limits());
           backend.Compute(request.basis, request.mode);
           Text(res, 202, "computing " + request.basis + " " + request.mode);
         }));
  s.Post("/reference", guarded([&backend](const httplib::Request& req, httplib::Response& res) {
           std::vector<std::pair<std::string, std::string>> query;
           for (const auto& [name, value] : req.params) {
             if (name != "mode" && name != "env") throw Error(name + ": unknown parameter (expected mode, env)");
             query.emplace_back(name, value);
           }
           const FrameRequest request = ParseFrameRequest(query, backend.Defaults(), backend.Limits());
           backend.MeasureReference(request);
           Text(res, 202, "measuring the reference");
         }));
  s.Get("/error", guarded([&backend](const httplib::Request& req, httplib::Response& res) {
          const FrameRequest request = ParseFrameRequest(Query(req), backend.Defaults(), backend.Limits());
          res.set_content(backend.ErrorJson(request), "application/json");
          res.set_header("Cache-Control", "no-store");
        }));
  const auto not_allowed = [](const httplib::Request& req, httplib::Response& res) {
    Text(res, 405, req.method + " " + req.path + ": not allowed (the page uses GET, and POST for /compute, /reference and /input)");
  };
  s.Put(".*", not_allowed);
  s.Delete(".*", not_allowed);
  s.Patch(".*", not_allowed);
  s.Options(".*", not_allowed);
  s.Post(".*", not_allowed);  // after /compute, /reference and /input, which match first
  s.set_error_handler([](const httplib::Request& req, httplib::Response& res) {
    if (res.body.empty()) Text(res, res.status, std::to_string(res.status) + ": " + req.method + " " + req.path);
  });

  port_ = port == 0 ? s.bind_to_any_port(bind) : (s.bind_to_port(bind, port) ? port : -1);
  if (port_ <= 0)
    throw Error("--bind " + bind + " --port " + std::to_string(port) +
                ": cannot listen there (the port is taken, or the address is not this machine's)");
  impl_->hosts = AllowedHosts(bind, port_);
}

ViewServer::~ViewServer() { Stop(); }

std::string ViewServer::Address() const {
  const std::string host = bind_.find(':') != std::string::npos ? "[" + bind_ + "]" : bind_;
  return "http://" + host + ":" + std::to_string(port_) + "/";
}

void ViewServer::Serve() {
  serving_ = true;
  if (!stopping_) impl_->server.listen_after_bind();
  serving_ = false;
}

void ViewServer::Stop() {
  stopping_ = true;
  impl_->streams.StopAll();
  // The library's stop() does nothing before its listening loop has started: a Serve already
  // entered is waited for until it listens (or returns), one entered later sees stopping_.
  while (serving_ && !impl_->server.is_running()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  impl_->server.stop();
}

}  // namespace prt
