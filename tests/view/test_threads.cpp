// The threads tier of src/view (tests/README.md, "Tiers"): prt view's server in this process,
// before a stand-in scene that counts what it is asked. The server's threads are made as
// connections come (view/growing_pool.h) and run the HTTP library's handlers: clients on threads of their own ask at once for the page, the state
// and frames (each frame checked against the request it answers), streams draw and send while
// their pages' inputs arrive on other threads, the server is stopped while they ask and stream,
// and ThreadSanitizer watches the handlers meet on the backend, the streams and the server.
#include <doctest/doctest.h>

#include <atomic>
#include <future>
#include <chrono>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "core/error.h"
#include "tests/threads_util.h"
#include "tests/view/http_client.h"
#include "tests/view/stand_in_backend.h"
#include "tests/view/stream_client.h"
#include "view/frame_stream.h"
#include "view/late_backend.h"
#include "view/view_server.h"

namespace prt {

TEST_SUITE("view") {
  TEST_CASE("threads: clients at once get their own frames, the page and the state; the server stops while they ask") {
    test::StandInBackend backend;
    ViewServer server(backend, "127.0.0.1", 0);
    test::UseToken(server.port(), server.Token());
    std::thread serving([&] { server.Serve(); });
    constexpr int kClients = 6, kRounds = 8;
    std::atomic<int> wrong{0}, answered{0};
    test::OnThreads(kClients, [&](int c) {
      for (int r = 0; r < kRounds; ++r) {
        const int width = 16 + c;  // each client its own size: its frames' bytes are its own
        // Six clients at once may find the draw queue's four places taken (view/draw_queue.h): a
        // 503 is asked again, after a while, as its Retry-After tells a client to.
        test::HttpReply frame;
        for (int tries = 0; tries < 100; ++tries) {
          frame = test::Request(server.port(), "/frame?size=" + std::to_string(width) + "x16");
          if (frame.status != 503) break;
          std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        const test::HttpReply state = test::Request(server.port(), "/state");
        const test::HttpReply page = test::Request(server.port(), "/");
        answered += frame.status == 200 && state.status == 200 && page.status == 200;
        if (frame.body != std::string(std::size_t(3) * width * 16, char(width))) ++wrong;
      }
    });
    CHECK(wrong == 0);
    CHECK(answered == kClients * kRounds);
    CHECK(backend.frames() == kClients * kRounds);

    // Stopped while clients still ask: Serve returns, and every request either was answered
    // whole or found no server. The frames are larger than a socket's buffers, so that the stop
    // comes while responses are being written.
    std::atomic<bool> asking{true};
    std::atomic<int> torn{0};
    std::vector<std::thread> late;
    for (int c = 0; c < 3; ++c)
      late.emplace_back([&] {
        while (asking) {
          const test::HttpReply frame = test::Request(server.port(), "/frame?size=600x600");
          if (frame.status == 200 && frame.body != std::string(std::size_t(3) * 600 * 600, char(600 % 256))) ++torn;
        }
      });
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    server.Stop();
    serving.join();
    asking = false;
    for (auto& t : late) t.join();
    CHECK(torn == 0);
  }

  TEST_CASE("threads: streams draw while their inputs and acknowledgements come on other threads; Stop ends them at once") {
    test::StandInBackend backend;
    ViewServer server(backend, "127.0.0.1", 0);
    test::UseToken(server.port(), server.Token());
    std::thread serving([&] { server.Serve(); });
    constexpr int kPages = 4, kInputs = 12;
    std::atomic<int> wrong{0}, disordered{0};
    test::OnThreads(kPages, [&](int c) {
      const std::string name = "00000000000000000000000000000" + std::to_string(100 + c);
      test::StreamClient stream(server.port(), name, "size=16x8", 1);
      if (stream.status() != 200) return void(++wrong);
      // The page's inputs from a thread of their own, each a size of its own, while this thread
      // reads and acknowledges: each frame's bytes are its size, so a frame drawn for another
      // input or another page shows.
      std::atomic<std::uint32_t> shown{0};
      std::thread inputs([&] {
        for (int i = 2; i <= kInputs; ++i)
          if (test::PostInput(server.port(), name, "shown=" + std::to_string(shown.load()) + "&input=" +
                                                      std::to_string(i) + "&size=" + std::to_string(16 + i) + "x8") != 204)
            ++wrong;
      });
      std::uint32_t last = 0, input = 0;
      const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
      while (input != kInputs) {
        const test::StreamRecord r = stream.Next(30.0);
        if (r.kind == "PRTK" && std::chrono::steady_clock::now() < deadline) continue;
        if (r.kind != "PRTF") { ++wrong; break; }
        if (r.frame != last + 1 || r.input < input) ++disordered;
        last = r.frame;
        input = r.input;
        const int width = input == 1 ? 16 : 16 + static_cast<int>(input);
        if (r.Rgb() != std::string(std::size_t(3) * width * 8, char(width))) ++wrong;
        shown = r.frame;
        if (test::PostInput(server.port(), name, "shown=" + std::to_string(r.frame)) != 204) ++wrong;
      }
      inputs.join();
    });
    CHECK(wrong == 0);
    CHECK(disordered == 0);

    // Streams open and waiting when the server stops: Serve returns without waiting for them.
    std::vector<std::unique_ptr<test::StreamClient>> open;
    for (int c = 0; c < 3; ++c) {
      open.push_back(std::make_unique<test::StreamClient>(server.port(), "0000000000000000000000000000020" + std::to_string(c), "", 1));
      CHECK(open.back()->status() == 200);
    }
    // Serve returns when Stop wakes the streams, well before their next keep-alive would have ended
    // them (an order of events, not a speed).
    auto served = std::async(std::launch::async, [&] { serving.join(); });
    server.Stop();
    CHECK(served.wait_for(kKeepAliveAfter / 2) == std::future_status::ready);
    served.get();
  }

  TEST_CASE("threads: a late backend answers 409 while starting and its scene once Ready is called from another thread") {
    test::StandInBackend scene;
    LateBackend late;
    ViewServer server(late, "127.0.0.1", 0);
    test::UseToken(server.port(), server.Token());
    std::thread serving([&] { server.Serve(); });
    std::atomic<bool> ready{false};
    std::atomic<int> wrong{0}, early{0}, served{0};
    std::thread make([&] {
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
      late.Ready(scene);
      ready = true;  // after: a client that saw it must find the scene
    });
    test::OnThreads(3, [&](int) {
      for (int i = 0; i < 40; ++i) {
        const bool was_ready = ready;
        const test::HttpReply frame = test::Request(server.port(), "/frame?size=16x8");
        const test::HttpReply state = test::Request(server.port(), "/state");
        if (frame.status == 409 && frame.body.find("starting") != std::string::npos) {
          ++early;
          if (was_ready) ++wrong;  // once ready, never starting again
        } else if (frame.status == 200 && frame.body == std::string(3 * 16 * 8, char(16))) {
          ++served;
        } else {
          ++wrong;
        }
        if (state.status != 200) ++wrong;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
      }
    });
    make.join();
    CHECK(wrong == 0);
    CHECK(early > 0);
    CHECK(served > 0);
    server.Stop();
    serving.join();
  }

  TEST_CASE("threads: a server stopped before it serves does not serve, whichever thread gets there first") {
    test::StandInBackend backend;
    for (const bool stop_first : {true, false}) {
      CAPTURE(stop_first);
      ViewServer server(backend, "127.0.0.1", 0);
      test::UseToken(server.port(), server.Token());
      if (stop_first) server.Stop();
      std::promise<void> served;
      std::future<void> done = served.get_future();
      std::thread serving([&] {
        server.Serve();
        served.set_value();
      });
      if (!stop_first) server.Stop();  // racing Serve's start: it listens first or sees the stop
      const bool returned = done.wait_for(std::chrono::seconds(3)) == std::future_status::ready;
      CHECK(returned);
      if (!returned) server.Stop();  // listening after all: stopped now, so that the test ends
      serving.join();
    }
  }
}

}  // namespace prt
