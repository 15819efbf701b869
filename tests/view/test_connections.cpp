// The threads tier of src/view's connections (tests/README.md, "Tiers"): prt view's server in
// this process before a stand-in scene, facing the clients its users met: connections that
// trickle their request a line at a time, a crowd asking for large frames at once, requests an
// attacker's page could make, and the HTTP edges a browser never sends. The clock is read
// only as liveness bounds and to order events (the page's state answered while every trickler
// is still open, before any deadline could have freed a thread).
#include <doctest/doctest.h>

#include <atomic>
#include <chrono>
#include <future>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include "core/error.h"
#include "tests/threads_util.h"
#include "tests/view/http_client.h"
#include "tests/view/stand_in_backend.h"
#include "tests/view/stream_client.h"
#include "view/draw_queue.h"
#include "view/growing_pool.h"
#include "view/request_guard.h"
#include "view/view_server.h"

namespace prt {
namespace {

using Clock = std::chrono::steady_clock;
/// A server on a free loopback port, serving on a thread of its own until destroyed.
struct Served {
  explicit Served(ViewBackend& backend, const std::string& bind = "127.0.0.1")
      : server(backend, bind, 0), serving([this] { server.Serve(); }) {
    test::UseToken(server.port(), server.Token());
  }
  ~Served() {
    server.Stop();
    serving.join();
  }
  ViewServer server;
  std::thread serving;
};

/// What the server has sent on `fd` so far (without waiting).
std::string Received(int fd) {
  std::string all;
  char buffer[4096];
  for (;;) {
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, 0) <= 0) break;
    const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
    if (n <= 0) break;
    all.append(buffer, static_cast<std::size_t>(n));
  }
  return all;
}

bool Send(int fd, const std::string& bytes) {
  return ::send(fd, bytes.data(), bytes.size(), MSG_NOSIGNAL) == static_cast<ssize_t>(bytes.size());
}

}  // namespace

TEST_SUITE("view") {
  TEST_CASE("threads: 40 clients trickling their headers a line a second leave /state answered at once, and each is cut off at its request's deadline") {
    test::StandInBackend backend(0);
    Served s(backend);
    const int port = s.server.port();
    constexpr int kTricklers = 40;  // more than the 32 threads of the server's old pool
    std::vector<int> fds;
    for (int i = 0; i < kTricklers; ++i) {
      fds.push_back(test::Connect(port));
      REQUIRE(Send(fds.back(), "GET /state HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) + "\r\n"));
    }
    // And one more that trickles its request line itself, a byte a second.
    const int request_line = test::Connect(port);
    // A line a second on each: within the library's 5 s read timeout, which every byte restarts.
    std::atomic<bool> trickling{true};
    std::thread trickler([&] {
      for (int line = 0; trickling && line < 14; ++line) {
        for (const int fd : fds) Send(fd, "X-Line-" + std::to_string(line) + ": 1\r\n");
        Send(request_line, "G");
        std::this_thread::sleep_for(std::chrono::seconds(1));
      }
    });
    // The page's state, asked four times a second while they trickle: each answered while every
    // trickler is still open, so not by waiting for a thread their deadlines would free.
    int answered = 0, asked = 0;
    for (const auto end = Clock::now() + std::chrono::seconds(4); Clock::now() < end; ++asked) {
      const bool ok = test::Request(port, "/state").status == 200;
      int open = 0;
      for (const int fd : fds) open += test::StillOpen(fd);
      answered += ok && open == kTricklers;
      std::this_thread::sleep_for(std::chrono::milliseconds(250));
    }
    CHECK(answered == asked);
    // Each request had 5 s from its first byte: by 9 s every trickler got 408 and was closed,
    // though its lines still come.
    std::this_thread::sleep_for(std::chrono::seconds(5));
    int cut = 0;
    for (const int fd : fds) {
      const std::string reply = Received(fd);
      cut += reply.rfind("HTTP/1.1 408", 0) == 0 && !test::StillOpen(fd);
    }
    CHECK(cut == kTricklers);
    // The request line too: cut off at the deadline, with an answer (the library writes none).
    CHECK(Received(request_line).rfind("HTTP/1.1 408", 0) == 0);
    CHECK_FALSE(test::StillOpen(request_line));
    trickling = false;
    trickler.join();
    for (const int fd : fds) ::close(fd);
    ::close(request_line);
  }

  TEST_CASE("threads: 50 clients asking for frames at once beside a page's stream: one drawn at a time, four waiting, the rest told 503 at once, /state answered meanwhile") {
    test::StandInBackend backend(150);
    Served s(backend);
    const int port = s.server.port();
    constexpr int kClients = 50;
    std::atomic<int> drawn{0}, busy{0}, other{0};
    std::atomic<bool> crowd{true};
    std::atomic<int> states{0};
    std::thread state([&] {
      while (crowd) {
        states += test::Request(port, "/state").status == 200;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
      }
    });
    // The page's own stream, a new input for each frame it shows, all through the crowd: its
    // frames are drawn in turn with the crowd's, never beside them.
    const std::string name(16, 'a');
    test::StreamClient page(port, name, "size=12x8", 0);
    REQUIRE(page.status() == 200);
    std::atomic<int> page_frames{0};
    std::thread pager([&] {
      for (std::uint64_t input = 1; crowd; ++input) {
        const test::StreamRecord r = page.Next(10.0);
        if (r.kind.empty()) break;
        if (r.kind != "PRTF") continue;
        ++page_frames;
        test::PostInput(port, name, "shown=" + std::to_string(r.frame) + "&input=" + std::to_string(input) +
                                        "&size=12x8&quality=interactive&angle=" + std::to_string(input));
      }
    });
    test::OnThreads(kClients, [&](int c) {
      const int width = 16 + c;
      const test::HttpReply frame = test::Request(port, "/frame?size=" + std::to_string(width) + "x8");
      if (frame.status == 200 && frame.body == std::string(std::size_t(3) * width * 8, char(width)))
        ++drawn;
      else if (frame.status == 503 && frame.Header("Retry-After") == "1")
        ++busy;
      else
        ++other;
    });
    crowd = false;
    state.join();
    pager.join();
    CHECK(page_frames >= 2);
    CHECK(other == 0);
    CHECK(drawn + busy == kClients);
    CHECK(drawn >= 1);
    CHECK(busy >= 1);  // 50 at once are more than one drawing and kWaitingRequests waiting
    CHECK(backend.most_at_once() == 1);
    CHECK(states >= 1);  // the state answered during the crowd
  }

  TEST_CASE("threads: DrawQueue: one turn at a time, the page's frames first, requests in order, at most N waiting, bytes held until sent") {
    DrawQueue queue(2, 100);
    std::vector<std::string> order;
    std::mutex order_mutex;
    const auto note = [&](const std::string& what) {
      std::lock_guard<std::mutex> lock(order_mutex);
      order.push_back(what);
    };
    const auto noted = [&] {
      std::lock_guard<std::mutex> lock(order_mutex);
      return order;
    };
    // Until the queue has `pages` and `requests` waiting (a liveness bound of a minute).
    const auto wait_for = [&](std::size_t pages, std::size_t requests) {
      for (const auto end = Clock::now() + std::chrono::minutes(1); Clock::now() < end;) {
        const DrawQueue::Waiting w = queue.Waiters();
        if (w.pages == pages && w.requests == requests) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
      return false;
    };
    std::shared_ptr<void> first_hold;
    DrawQueue::Turn first = queue.Request(60, &first_hold);
    CHECK(queue.Reserved() == 60);
    // Two requests wait (a third is refused), then a page frame: the page goes first when the
    // turn is given back, then the requests in the order they came.
    std::shared_ptr<void> hold_a, hold_b;
    std::thread a([&] {
      try {
        DrawQueue::Turn t = queue.Request(30, &hold_a);
        note("a");
      } catch (const Busy&) {  // stopped: the test has failed already
      }
    });
    REQUIRE(wait_for(0, 1));
    std::thread b([&] {
      try {
        DrawQueue::Turn t = queue.Request(30, &hold_b);
        note("b");
      } catch (const Busy&) {  // stopped: the test has failed already
      }
    });
    REQUIRE(wait_for(0, 2));
    // A third is refused at once; one that waits instead is ended by Stop, failing the test.
    std::shared_ptr<void> refused;
    auto third = std::async(std::launch::async, [&] {
      try {
        DrawQueue::Turn t = queue.Request(1, &refused);
        return std::string("drawn");
      } catch (const Busy& e) {
        return std::string(e.what());
      }
    });
    if (third.wait_for(std::chrono::minutes(1)) != std::future_status::ready) {
      queue.Stop();
      first.Release();
      a.join();
      b.join();
      FAIL_CHECK("a third request waited: " << third.get());
      return;
    }
    CHECK(third.get().find("busy: 2 frames are waiting") == 0);
    std::thread page([&] {
      DrawQueue::Turn t = queue.Page();
      note("page");
    });
    REQUIRE(wait_for(1, 2));
    first.Release();
    page.join();
    a.join();  // 60 + 30 <= 100: drawn while the first frame's bytes are still held
    // b's 30 would pass 100 with the first's 60 and a's 30 held: it waits for a send to end.
    CHECK(wait_for(0, 1));
    CHECK(noted() == std::vector<std::string>{"page", "a"});
    first_hold.reset();
    b.join();
    CHECK(noted() == std::vector<std::string>{"page", "a", "b"});
    CHECK(queue.Reserved() == 60);
    hold_a.reset();
    hold_b.reset();
    CHECK(queue.Reserved() == 0);
    // A frame larger than the whole budget is drawn alone, and a stopped queue gives no turn.
    std::shared_ptr<void> big;
    { DrawQueue::Turn t = queue.Request(500, &big); }
    big.reset();
    queue.Stop();
    CHECK_THROWS_AS(queue.Page(), Busy);
    CHECK_THROWS_AS(queue.Request(1, &big), Busy);
  }

  TEST_CASE("threads: a requested frame holds its bytes until it is sent: the next one past the budget waits for a slow reader") {
    // Frames of 48 MiB, more than the socket buffers take, and a budget of 64 MiB: while the
    // first is unread, the second cannot be drawn.
    test::StandInBackend backend(0);
    ViewServer server(backend, "127.0.0.1", 0, std::size_t(64) << 20);
    test::UseToken(server.port(), server.Token());
    std::thread serving([&] { server.Serve(); });
    const int port = server.port();
    const std::string frame = "GET /frame?size=4096x4096 HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) +
                              "\r\n" + test::TokenHeader(port) + "Connection: close\r\n\r\n";
    const int slow = test::Connect(port);
    REQUIRE(Send(slow, frame));
    for (const auto end = Clock::now() + std::chrono::minutes(1); backend.frames() < 1 && Clock::now() < end;)
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    REQUIRE(backend.frames() == 1);
    auto second = std::async(std::launch::async, [&] { return test::SendRaw(port, frame).body.size(); });
    // Not drawn while the first is unread (a second of looking; drawn at once were the first's
    // bytes given back when drawn).
    CHECK(second.wait_for(std::chrono::seconds(1)) == std::future_status::timeout);
    CHECK(backend.frames() == 1);
    // The first read whole: then the second is drawn and sent.
    std::size_t got = 0;
    char buffer[1 << 16];
    for (ssize_t n; (n = ::recv(slow, buffer, sizeof buffer, 0)) > 0;) got += static_cast<std::size_t>(n);
    ::close(slow);
    CHECK(got > std::size_t(3) * 4096 * 4096);
    CHECK(second.get() == std::size_t(3) * 4096 * 4096);
    CHECK(backend.frames() == 2);
    server.Stop();
    serving.join();
  }

  TEST_CASE("threads: a frame being sent when the server stops is sent whole") {
    // A 48 MiB frame, more than the socket buffers take: its first bytes have arrived, the rest
    // are still being written, when the server is stopped. The client then reads on: the whole
    // body, never a cut-off one after a 200 (nor the connection closed at the stop).
    test::StandInBackend backend(0);
    ViewServer server(backend, "127.0.0.1", 0);
    test::UseToken(server.port(), server.Token());
    std::thread serving([&] { server.Serve(); });
    const int port = server.port();
    const int fd = test::Connect(port);
    REQUIRE(Send(fd, "GET /frame?size=4096x4096 HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) + "\r\n" +
                         test::TokenHeader(port) + "Connection: close\r\n\r\n"));
    std::string got;
    char buffer[1 << 16];
    pollfd p{fd, POLLIN, 0};
    REQUIRE(::poll(&p, 1, 60000) == 1);  // liveness only: the answer has begun
    const ssize_t first = ::recv(fd, buffer, sizeof buffer, 0);
    REQUIRE(first > 0);
    got.append(buffer, static_cast<std::size_t>(first));
    server.Stop();
    for (ssize_t n; (n = ::recv(fd, buffer, sizeof buffer, 0)) > 0;) got.append(buffer, static_cast<std::size_t>(n));
    ::close(fd);
    serving.join();
    const std::size_t end = got.find("\r\n\r\n");
    REQUIRE(end != std::string::npos);
    CHECK(got.rfind("HTTP/1.1 200", 0) == 0);
    const std::size_t size = std::size_t(3) * 4096 * 4096;
    CHECK(got.size() - (end + 4) == size);
    CHECK(got.find_first_not_of(char(4096 % 256), end + 4) == std::string::npos);
  }

  TEST_CASE("threads: GrowingPool: a thread for each job waiting, up to its maximum; shutdown runs what is queued") {
    constexpr int kMax = 6;
    std::atomic<int> running{0}, most{0}, ran{0};
    std::atomic<bool> release{false};
    {
      GrowingPool pool(kMax);
      for (int i = 0; i < 10; ++i)
        pool.enqueue([&] {
          const int now = ++running;
          for (int m = most.load(); now > m && !most.compare_exchange_weak(m, now);) {
          }
          while (!release) std::this_thread::sleep_for(std::chrono::milliseconds(1));
          --running;
          ++ran;
        });
      // Six jobs run at once, each on a thread of its own; four wait for one of them.
      for (const auto end = Clock::now() + std::chrono::minutes(1); most < kMax && Clock::now() < end;)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      CHECK(most == kMax);
      CHECK(pool.Threads() == std::size_t(kMax));
      release = true;
      pool.shutdown();  // the four queued jobs run before the threads end
      CHECK(ran == 10);
      CHECK(most == kMax);
      // After shutdown a job still runs (it closes its connection), here and now.
      bool inline_ran = false;
      pool.enqueue([&] { inline_ran = true; });
      CHECK(inline_ran);
    }
  }

  TEST_CASE("threads: only the page prt served draws: a request without the run's token is refused, with it served") {
    test::StandInBackend backend(0);
    Served s(backend);
    const int port = s.server.port();
    const std::string token = s.server.Token();
    CHECK(token.size() == 32);
    // The page carries it; an <img> of another page of this machine does not know it.
    CHECK(test::SendRaw(port, "GET / HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) + "\r\nConnection: close\r\n\r\n")
              .body.find("<meta name=\"prt-token\" content=\"" + token + "\">") != std::string::npos);
    const std::string host = "Host: 127.0.0.1:" + std::to_string(port) + "\r\n";
    const auto raw = [&](const std::string& target, const std::string& extra = "") {
      return test::SendRaw(port, "GET " + target + " HTTP/1.1\r\n" + host + extra + "Connection: close\r\n\r\n");
    };
    const test::HttpReply img = raw("/frame.png?size=8x8", "Sec-Fetch-Site: same-site\r\n");
    CHECK(img.status == 403);
    CHECK(img.body.find("no token") != std::string::npos);
    CHECK(raw("/frame?size=8x8", "X-Prt-Token: " + std::string(32, '0') + "\r\n").status == 403);
    CHECK(raw("/frame?size=8x8&token=" + token.substr(0, 31)).status == 403);
    CHECK(raw("/command?token=").status == 403);
    CHECK(raw("/frame?size=8x8", "X-Prt-Token: " + token + "\r\n").status == 200);
    CHECK(raw("/frame?size=8x8&token=" + token).status == 200);  // a download link's way
    CHECK(raw("/command?token=" + token).status == 200);
    // The page's files and its state need none.
    CHECK(raw("/view.js").status == 200);
    CHECK(raw("/state").status == 200);
    CHECK(backend.frames() == 2);
  }

  TEST_CASE("threads: HTTP edges: two Hosts, a Host in capitals, POST without length, a body on a GET, a %00 in a value") {
    test::StandInBackend backend(0);
    Served s(backend);
    const int port = s.server.port();
    const std::string p = std::to_string(port), token = "X-Prt-Token: " + s.server.Token() + "\r\n";
    // Two Host headers: refused, not the first taken.
    const test::HttpReply two =
        test::SendRaw(port, "GET /state HTTP/1.1\r\nHost: 127.0.0.1:" + p + "\r\nHost: evil.example:" + p + "\r\n\r\n");
    CHECK(two.status == 400);
    CHECK(two.body.find("two Host headers") != std::string::npos);
    // Host names have no case.
    CHECK(test::SendRaw(port, "GET /state HTTP/1.1\r\nHost: LOCALHOST:" + p + "\r\nConnection: close\r\n\r\n").status == 200);
    // A POST without Content-Length: 411, with the reason.
    const test::HttpReply post = test::SendRaw(port, "POST /compute?basis=sh&mode=shadowed HTTP/1.1\r\nHost: 127.0.0.1:" +
                                                         p + "\r\nOrigin: http://127.0.0.1:" + p + "\r\n" + token + "\r\n");
    CHECK(post.status == 411);
    CHECK(post.body.find("Content-Length") != std::string::npos);
    // A GET with a 2 KiB body: 413, and the connection closed, its body never read as a request.
    const std::string body(2048, 'x');
    const test::HttpReply big = test::SendRaw(port, "GET /state HTTP/1.1\r\nHost: 127.0.0.1:" + p +
                                                        "\r\nContent-Length: 2048\r\n\r\n" + body);
    CHECK(big.status == 413);
    CHECK(big.head.find("Connection: close") != std::string::npos);
    const test::HttpReply small = test::SendRaw(port, "GET /state HTTP/1.1\r\nHost: 127.0.0.1:" + p +
                                                          "\r\nContent-Length: 5\r\n\r\nGET /");
    CHECK(small.status == 400);
    CHECK(small.body.find("a GET with a body") != std::string::npos);
    // A Range: refused (the library would not bound it by the frame's length).
    const test::HttpReply range = test::Request(port, "/frame?size=8x8", "GET", "Range: bytes=100-200000\r\n");
    CHECK(range.status == 416);
    CHECK(range.body.size() < 200);
    // A request refused for its Origin with a body: its body is never read as a request.
    const test::HttpReply smuggled = test::SendRaw(
        port, "POST /compute HTTP/1.1\r\nHost: 127.0.0.1:" + p + "\r\nOrigin: http://evil.example\r\n" + token +
                  "Content-Length: 40\r\n\r\nGET /frame?size=9x9 HTTP/1.1\r\nHost: x\r\n\r\n");
    CHECK(smuggled.status == 403);
    CHECK(smuggled.head.find("Connection: close") != std::string::npos);
    CHECK(smuggled.body.find("HTTP/1.1") == std::string::npos);  // one answer, not two
    // 70 KiB of headers: 431, and closed.
    std::string headers;
    for (int i = 0; i < 1100; ++i) headers += "X-Filler-" + std::to_string(i) + ": " + std::string(50, 'a') + "\r\n";
    const test::HttpReply huge = test::SendRaw(port, "GET /state HTTP/1.1\r\nHost: 127.0.0.1:" + p + "\r\n" + headers + "\r\n");
    CHECK(huge.status == 431);
    // A %00 in a value: the whole value in the message, escaped.
    const test::HttpReply nul = test::Request(port, "/frame?view=radi%00ance");
    CHECK(nul.status == 400);
    CHECK(nul.body.find("view=radi\\x00ance") != std::string::npos);
    CHECK(backend.frames() == 0);
  }

  TEST_CASE("threads: a server bound to every address answers under this machine's addresses and name") {
    test::StandInBackend backend(0);
    Served s(backend, "0.0.0.0");
    const int port = s.server.port();
    CHECK(s.server.Address() == "http://127.0.0.1:" + std::to_string(port) + "/");
    const MachineNames machine = ThisMachine();
    REQUIRE(!machine.hostname.empty());
    const auto state = [&](const std::string& host) {
      return test::SendRaw(port, "GET /state HTTP/1.1\r\nHost: " + host + ":" + std::to_string(port) +
                                     "\r\nConnection: close\r\n\r\n").status;
    };
    CHECK(state("127.0.0.1") == 200);
    CHECK(state("localhost") == 200);
    CHECK(state(machine.hostname) == 200);
    for (const std::string& address : machine.addresses)
      if (address.find(':') == std::string::npos) CHECK(state(address) == 200);
    CHECK(state("evil.example") == 403);
  }
}

}  // namespace prt
