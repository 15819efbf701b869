#include "view/view_server.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <map>
#include <mutex>
#include <optional>
#include <random>
#include <stdexcept>
#include <string_view>
#include <thread>
#include <utility>
#include <vector>

#include <httplib.h>
#include <sys/socket.h>

#include "core/error.h"
#include "core/text.h"
#include "io/png_io.h"
#include "view/deadline_server.h"
#include "view/draw_queue.h"
#include "view/frame_stream.h"
#include "view/growing_pool.h"
#include "view/page.h"
#include "view/request_guard.h"
#include "view/stream_record.h"

namespace prt {
namespace {

/// Seconds a connection may take to send its request (view/deadline_server.h) or to read a
/// response before it is dropped.
constexpr int kTimeoutSeconds = 5;
/// Threads serving connections at most (view/growing_pool.h): made as connections come, each
/// held by one connection while it lasts, so that clients that wait leave threads for the page.
constexpr std::size_t kMaxThreads = 256;
/// Requested frames (/frame, /frame.png) waiting for their turn at most (view/draw_queue.h).
constexpr std::size_t kWaitingRequests = 4;

void Text(httplib::Response& res, int status, const std::string& text) {
  res.status = status;
  res.set_content(text + "\n", "text/plain; charset=utf-8");
}

/// A request refused whatever its parameters (403).
struct Refused : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The parameter that carries the run's token (view/request_guard.h), and its header.
constexpr const char* kTokenParam = "token";
constexpr const char* kTokenHeader = "X-Prt-Token";

/// A request's parameters but the token.
std::vector<std::pair<std::string, std::string>> Query(const httplib::Request& req) {
  std::vector<std::pair<std::string, std::string>> query;
  for (const auto& [name, value] : req.params)
    if (name != kTokenParam) query.emplace_back(name, value);
  return query;
}

/// Every value of header `name`.
std::vector<std::string> Values(const httplib::Request& req, const char* name) {
  std::vector<std::string> values;
  const auto [begin, end] = req.headers.equal_range(name);
  for (auto it = begin; it != end; ++it) values.push_back(it->second);
  return values;
}

/// A new run's token: 128 random bits in hexadecimal.
std::string NewToken() {
  std::random_device random;
  std::string token;
  for (int i = 0; i < 4; ++i) {
    char part[9];
    std::snprintf(part, sizeof part, "%08x", static_cast<unsigned>(random()));
    token += part;
  }
  return token;
}

/// The page's index.html with the run's token in it, for the page's script to send.
std::string PageWithToken(std::string_view html, const std::string& token) {
  std::string page(html);
  const std::string meta = "\n<meta name=\"prt-token\" content=\"" + token + "\">";
  const std::size_t head = page.find("<head>");
  page.insert(head == std::string::npos ? 0 : head + 6, meta);
  return page;
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
  for (const auto& [name, value] : Query(req))
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
  DeadlineServer server{std::chrono::seconds(kTimeoutSeconds)};
  std::vector<std::string> hosts;
  const std::string token = NewToken();
  Streams streams;
  DrawQueue draws;

  explicit Impl(std::size_t held_frame_bytes) : draws(kWaitingRequests, held_frame_bytes) {}
};

ViewServer::ViewServer(ViewBackend& backend, const std::string& bind, int port, std::size_t held_frame_bytes)
    : impl_(std::make_unique<Impl>(held_frame_bytes)), bind_(bind) {
  DeadlineServer& s = impl_->server;
  s.set_read_timeout(kTimeoutSeconds, 0);
  s.set_write_timeout(kTimeoutSeconds, 0);
  s.set_payload_max_length(kMaxBody);
  s.set_keep_alive_max_count(10000);  // the page asks for frame after frame on one connection
  // Each connection holds a thread while it lasts: the pool grows with them, so that clients
  // which stall (each dropped after its timeout) leave threads for the others.
  s.new_task_queue = [] { return new GrowingPool(kMaxThreads); };
  // The library's default, SO_REUSEPORT, would let a second server share the port and take half
  // its connections: SO_REUSEADDR alone lets a restart take the port of one just ended, no more.
  int listening = -1;
  s.set_socket_options([&listening](int sock) {
    int yes = 1;
    ::setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    listening = sock;
  });
  s.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    RequestHead head;
    head.method = req.method;
    head.path = req.path;
    head.hosts = Values(req, "Host");
    head.origins = Values(req, "Origin");
    head.content_lengths = Values(req, "Content-Length");
    head.transfer_encodings = Values(req, "Transfer-Encoding");
    head.ranges = Values(req, "Range");
    head.fetch_site = req.get_header_value("Sec-Fetch-Site");
    head.token = req.has_header(kTokenHeader) ? req.get_header_value(kTokenHeader) : req.get_param_value(kTokenParam);
    head.params.assign(req.params.begin(), req.params.end());
    const Refusal refusal = Refuse(head, impl_->hosts, impl_->token);
    if (refusal.status == 0) return httplib::Server::HandlerResponse::Unhandled;
    if (refusal.close) {
      res.set_header("Connection", "close");
      DeadlineServer::CloseAfterResponse();
    }
    Text(res, refusal.status, refusal.why);
    return httplib::Server::HandlerResponse::Handled;
  });
  // Anything a handler throws is the request's fault or the scene's: an answer, never an end.
  const auto guarded = [](auto handler) {
    return [handler](const httplib::Request& req, httplib::Response& res) {
      try {
        handler(req, res);
      } catch (const Refused& e) {
        Text(res, 403, e.what());
      } catch (const Busy& e) {
        res.set_header("Retry-After", "1");
        Text(res, 503, e.what());
      } catch (const NotReady& e) {
        Text(res, 409, e.what());
      } catch (const Error& e) {
        Text(res, 400, e.what());
      } catch (const std::exception& e) {
        Text(res, 500, std::string("internal error: ") + e.what());
      }
    };
  };
  s.Get(R"(/|/[A-Za-z0-9_.-]+\.(html|js))", guarded([this](const httplib::Request& req, httplib::Response& res) {
          const std::optional<PageFile> file = FindPageFile(req.path);
          if (!file) return Text(res, 404, "not found: " + req.path);
          const bool html = std::string(file->type).rfind("text/html", 0) == 0;
          res.set_content(html ? PageWithToken(file->body, impl_->token) : std::string(file->body), file->type);
          res.set_header("Cache-Control", "no-store");
        }));
  s.Get("/state", guarded([&backend](const httplib::Request&, httplib::Response& res) {
          res.set_content(backend.StateJson(), "application/json");
          res.set_header("Cache-Control", "no-store");
        }));
  // A requested frame: drawn in its turn (view/draw_queue.h), its bytes reserved until sent.
  const auto frame = [this, &backend](const httplib::Request& req, bool png, httplib::Response& res) {
    const FrameRequest request = ParseFrameRequest(Query(req), backend.Defaults(), backend.Limits());
    std::shared_ptr<void> hold;
    double ms = 0.0;
    Image8 image;
    {
      const DrawQueue::Turn turn =
          impl_->draws.Request(std::size_t(3) * request.draw.width * request.draw.height, &hold);
      image = backend.Frame(request, &ms);
    }
    res.set_header("X-Prt-Size", std::to_string(image.width) + "x" + std::to_string(image.height));
    res.set_header("X-Prt-Draw-Ms", std::to_string(ms));
    res.set_header("Cache-Control", "no-store");
    if (png) res.set_header("Content-Disposition", "attachment; filename=\"prt-view.png\"");
    // A plain body, not a content provider: the library's provider loop gives up at a stop, which
    // would cut off a body whose length was already sent. The bytes stay reserved until sent.
    res.body = png ? EncodePng(image) : std::string(image.rgb.begin(), image.rgb.end());
    res.set_header("Content-Type", png ? "image/png" : "application/octet-stream");
    image = Image8();
    DeadlineServer::HoldUntilSent(std::move(hold));
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
                    Image8 image;
                    {
                      const DrawQueue::Turn turn = this->impl_->draws.Page();
                      image = backend.Frame(job.request, &ms);
                    }
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
           const std::vector<std::pair<std::string, std::string>> wanted = FrameParams(req);
           if (req.has_param("input")) {
             const std::uint64_t input = Count("input", req.get_param_value("input"));
             stream->Want(ParseFrameRequest(wanted, backend.Defaults(), backend.Limits()), input);
           } else if (!wanted.empty()) {
             throw Error(wanted.front().first + ": a frame parameter without input= (expected input=N with them)");
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
           for (const auto& [name, value] : Query(req)) {
             if (name != "basis" && name != "mode") throw Error(name + ": unknown parameter (expected basis, mode)");
             query.emplace_back(name, value);
           }
           request = ParseFrameRequest(query, request, backend.Limits());
           backend.Compute(request.basis, request.mode);
           Text(res, 202, "computing " + request.basis + " " + request.mode);
         }));
  s.Post("/reference", guarded([&backend](const httplib::Request& req, httplib::Response& res) {
           std::vector<std::pair<std::string, std::string>> query;
           for (const auto& [name, value] : Query(req)) {
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
    if (DeadlineServer::RequestExpired()) {
      res.set_header("Connection", "close");
      return Text(res, 408, "request: not whole within " + std::to_string(kTimeoutSeconds) + " s of its first byte (closed)");
    }
    if (DeadlineServer::RequestTooLarge()) {
      res.set_header("Connection", "close");
      return Text(res, 431, "request: over " + std::to_string(DeadlineServer::kMaxRequestBytes / 1024) + " KiB (closed)");
    }
    if (res.body.empty()) Text(res, res.status, std::to_string(res.status) + ": " + req.method + " " + Escaped(req.path));
  });

  port_ = port == 0 ? s.bind_to_any_port(bind) : (s.bind_to_port(bind, port) ? port : -1);
  // The library listens with a backlog of 5: a crowd connecting at once overflowed it, and the
  // connections past it waited a second for their SYN to be sent again. Listening again on the
  // bound socket only sets a longer backlog.
  if (port_ > 0 && listening >= 0) ::listen(listening, SOMAXCONN);
  s.set_socket_options(nullptr);
  if (port_ <= 0)
    throw Error("--bind " + bind + " --port " + std::to_string(port) +
                ": cannot listen there (the port is taken, or the address is not this machine's)");
  impl_->hosts = AllowedHosts(bind, port_, IsWildcard(bind) ? ThisMachine() : MachineNames{});
}

ViewServer::~ViewServer() { Stop(); }

const std::string& ViewServer::Token() const { return impl_->token; }

const std::vector<std::string>& ViewServer::Hosts() const { return impl_->hosts; }

std::string ViewServer::Address() const {
  // A wildcard bind is reached here through the loopback address.
  const std::string bind = bind_ == "0.0.0.0" ? "127.0.0.1" : bind_ == "::" ? "::1" : bind_;
  const std::string host = bind.find(':') != std::string::npos ? "[" + bind + "]" : bind;
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
  impl_->draws.Stop();
  // The library's stop() does nothing before its listening loop has started: a Serve already
  // entered is waited for until it listens (or returns), one entered later sees stopping_.
  while (serving_ && !impl_->server.is_running()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  impl_->server.stop();
}

}  // namespace prt
