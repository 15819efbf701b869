// prt view's frame stream (GET /stream, POST /input; src/view/frame_stream.h) as a page meets it,
// over sockets of the test's own: each input answered at interactive quality and then by its
// still frame, byte for byte the /frame of the same query; frames in order, never more than
// two ahead of what the page has shown; a page that stops reading frees its thread and stalls no
// other; a page that reconnects gets a new stream; what /input refuses.
#include <chrono>
#include <memory>
#include <thread>
#include <vector>

#include "tests/test_process.h"
#include "tests/view/stream_client.h"
#include "tests/view/view_process.h"

namespace prt::test {
namespace {

/// The page's stream names: 32 hexadecimal digits.
const std::string kName = "0123456789abcdef0123456789abcdef";
const std::string kOther = "fedcba9876543210fedcba9876543210";

/// Seconds a test waits for a record it expects: a frame of the small scene takes milliseconds.
constexpr double kWait = 30.0;
/// How long a test watches for a record that must not come: longer than the still frame's delay
/// (120 ms) and a frame's drawing, shorter than the keep-alive (2 s).
constexpr double kNothing = 0.6;

std::string Turned(int degrees) { return "angle=" + std::to_string(degrees); }

/// The next record that is not a keep-alive, within `seconds` in all (kind "" when none came).
StreamRecord NextFrame(StreamClient& s, double seconds = kWait) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  for (;;) {
    const double left = std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
    if (left <= 0) return {};
    StreamRecord r = s.Next(left);
    if (r.kind != "PRTK") return r;
  }
}

}  // namespace

TEST_SUITE("view") {

TEST_CASE("prt view's stream with wavelets: the interactive light is the coarser one, the still frame the still light's") {
  // The kept frame lights of one setting at the two qualities must stay apart, whichever comes
  // first: an interactive frame differs from the still light's at the same ssaa 1, and the still
  // frame after it is the /frame drawn before any interactive one.
  const std::string dir = ScratchDir("view_stream_wavelet");
  ViewProcess view(SmallViewArgs(dir), dir + "/stderr.txt");
  const int port = view.port();
  REQUIRE(Request(port, "/compute?basis=wavelet&mode=shadowed", "POST",
                  "Origin: http://127.0.0.1:" + std::to_string(port) + "\r\n").status == 202);
  WaitReady(port, "wavelet shadowed");
  const std::string q = "basis=wavelet&angle=35";
  const std::string still = Request(port, "/frame?" + q).body;
  const std::string still_ssaa1 = Request(port, "/frame?" + q + "&ssaa=1").body;
  REQUIRE(still.size() == 160u * 120u * 3u);
  StreamClient stream(port, kName, q, 1);
  REQUIRE(stream.status() == 200);
  const StreamRecord moving = NextFrame(stream);
  REQUIRE(moving.kind == "PRTF");
  CHECK((moving.flags & 1u) == 0u);
  CHECK(moving.Rgb() != still_ssaa1);  // not the still light
  const StreamRecord rest = NextFrame(stream);
  REQUIRE(rest.kind == "PRTF");
  CHECK((rest.flags & 1u) == 1u);
  CHECK(rest.Rgb() == still);
  // And the other way round: another angle, interactive first, then the still /frame at ssaa 1.
  REQUIRE(PostInput(port, kName, "shown=2&input=2&basis=wavelet&angle=70") == 204);
  const StreamRecord turned = NextFrame(stream);
  REQUIRE(turned.kind == "PRTF");
  CHECK(turned.Rgb() == Request(port, "/frame?basis=wavelet&angle=70&quality=interactive").body);
  CHECK(turned.Rgb() != Request(port, "/frame?basis=wavelet&angle=70&ssaa=1").body);
}

TEST_CASE("prt view's stream: each input at interactive quality, then its still frame, each the /frame of its query") {
  const std::string dir = ScratchDir("view_stream");
  ViewProcess view(SmallViewArgs(dir), dir + "/stderr.txt");
  const int port = view.port();
  StreamClient stream(port, kName, Turned(30), 1);
  REQUIRE(stream.status() == 200);
  CHECK(stream.head().find("Content-Type: application/octet-stream") != std::string::npos);

  // Input 1: an interactive frame at once, then (nothing new coming) its still frame.
  const StreamRecord moving = NextFrame(stream);
  REQUIRE(moving.kind == "PRTF");
  CHECK(moving.frame == 1);
  CHECK(moving.input == 1);
  CHECK((moving.flags & 1u) == 0u);
  CHECK(moving.width == 160);
  CHECK(moving.height == 120);
  const StreamRecord still = NextFrame(stream);
  REQUIRE(still.kind == "PRTF");
  CHECK(still.frame == 2);
  CHECK(still.input == 1);
  CHECK((still.flags & 1u) == 1u);
  // Every pixel opaque, and the RGB the /frame of the same query: still quality is the frame
  // `prt render` writes (the /frame tests compare it with render), interactive is quality=interactive.
  bool opaque = true;
  for (std::size_t i = 3; i < still.body.size(); i += 4) opaque = opaque && static_cast<unsigned char>(still.body[i]) == 255;
  CHECK(opaque);
  CHECK(still.Rgb() == Request(port, "/frame?" + Turned(30)).body);
  CHECK(moving.Rgb() == Request(port, "/frame?" + Turned(30) + "&quality=interactive").body);
  CHECK(moving.Rgb() != still.Rgb());  // ssaa 2 against 1: the quality differs where edges are

  // Two frames sent, none shown: the window is full, so a new input waits for the page.
  REQUIRE(PostInput(port, kName, "input=2&" + Turned(60)) == 204);
  CHECK(NextFrame(stream, kNothing).kind.empty());
  REQUIRE(PostInput(port, kName, "shown=2") == 204);
  const StreamRecord second = NextFrame(stream);
  REQUIRE(second.kind == "PRTF");
  CHECK(second.frame == 3);
  CHECK(second.input == 2);
  CHECK((second.flags & 1u) == 0u);
  CHECK(second.Rgb() == Request(port, "/frame?" + Turned(60) + "&quality=interactive").body);

  // An input older than the newest (a POST overtaken by a later one) is ignored: the next frame
  // is input 2's still frame.
  REQUIRE(PostInput(port, kName, "shown=3&input=1&" + Turned(90)) == 204);
  const StreamRecord second_still = NextFrame(stream);
  REQUIRE(second_still.kind == "PRTF");
  CHECK(second_still.input == 2);
  CHECK((second_still.flags & 1u) == 1u);
  CHECK(second_still.Rgb() == Request(port, "/frame?" + Turned(60)).body);

  // Inputs faster than the frames: the page's newest is drawn, never a queue of old ones, and
  // frames keep their order.
  REQUIRE(PostInput(port, kName, "shown=4") == 204);
  for (int input = 3; input <= 8; ++input) REQUIRE(PostInput(port, kName, "input=" + std::to_string(input) + "&" + Turned(input)) == 204);
  std::uint32_t last_frame = 4, last_input = 2;
  while (last_input != 8) {
    const StreamRecord r = NextFrame(stream);
    REQUIRE(r.kind == "PRTF");
    CHECK(r.frame == last_frame + 1);
    CHECK(r.input > last_input);
    last_frame = r.frame;
    last_input = r.input;
    REQUIRE(PostInput(port, kName, "shown=" + std::to_string(r.frame)) == 204);
  }
  CHECK(last_frame <= 4 + 6);

  // An input the scene cannot draw: an error record naming why, and the stream goes on.
  REQUIRE(PostInput(port, kName, "input=9&mode=interreflection") == 204);
  const StreamRecord refused = NextFrame(stream);
  CHECK(refused.kind == "PRTE");
  CHECK(refused.input == 9);
  CHECK(refused.body.find("not computed") != std::string::npos);
  REQUIRE(PostInput(port, kName, "shown=" + std::to_string(refused.frame) + "&input=10&" + Turned(5)) == 204);
  CHECK(NextFrame(stream).input == 10);

  // Idle: a keep-alive record within its 2 s, so that a page that has gone is noticed.
  const StreamRecord idle = stream.Next(kWait);
  const StreamRecord alive = idle.kind == "PRTF" ? stream.Next(kWait) : idle;  // input 10's still frame first
  CHECK(alive.kind == "PRTK");
}

TEST_CASE("prt view's stream: what /input and /stream refuse") {
  const std::string dir = ScratchDir("view_stream_refusals");
  ViewProcess view(SmallViewArgs(dir), dir + "/stderr.txt");
  const int port = view.port();
  CHECK(PostInput(port, kName, "shown=1") == 404);  // no such stream
  StreamClient stream(port, kName, "", 0);
  REQUIRE(stream.status() == 200);
  CHECK(PostInput(port, "0123", "shown=1") == 400);                                // too short a name
  CHECK(PostInput(port, "0123456789abcdefg123456789abcdef", "shown=1") == 400);    // not hexadecimal
  CHECK(PostInput(port, kName, "shown=-1") == 400);
  CHECK(PostInput(port, kName, "shown=1.5") == 400);
  CHECK(PostInput(port, kName, "input=x&angle=1") == 400);
  CHECK(PostInput(port, kName, "angle=1") == 400);            // a frame parameter without its input number
  CHECK(PostInput(port, kName, "input=5&angle=abc") == 400);  // the frame query checked as /frame's
  CHECK(PostInput(port, kName, "input=5&lmax=99") == 400);
  CHECK(Request(port, "/input?stream=" + kName + "&shown=1").status == 404);  // a GET changes nothing
  const std::string page = "X-Prt-Stream: 1\r\n", origin = "Origin: http://127.0.0.1:" + std::to_string(port) + "\r\n";
  CHECK(Request(port, "/input?stream=" + kName + "&shown=1", "POST", page).status == 403);  // no Origin
  CHECK(Request(port, "/input?stream=" + kName + "&shown=1", "POST", "Origin: http://evil.example\r\n" + page).status == 403);
  // Only prt's own page sends X-Prt-Stream (another page cannot without a preflight, which is
  // refused; an <img> or a form cannot at all): without it, no stream and no input.
  const HttpReply no_header = Request(port, "/input?stream=" + kName + "&shown=1", "POST", origin);
  CHECK(no_header.status == 403);
  CHECK(no_header.body.find("X-Prt-Stream") != std::string::npos);
  CHECK(Request(port, "/stream?stream=" + kOther).status == 403);
  CHECK(Request(port, "/stream?stream=" + kOther, "GET", "X-Prt-Stream: 0\r\n").status == 403);
  // No preflight passes: refused without an Origin (403), not allowed with the page's own (405).
  CHECK(Request(port, "/stream?stream=" + kOther, "OPTIONS", page).status == 403);
  CHECK(Request(port, "/stream?stream=" + kOther, "OPTIONS", origin + page).status == 405);
  StreamClient bad(port, kOther, "lmax=99", 0);
  CHECK(bad.status() == 400);
  StreamClient unnamed(port, "", "", 0);
  CHECK(unnamed.status() == 400);
  // Eight streams open at once, the most: a ninth is refused, saying so.
  {
    std::vector<std::unique_ptr<StreamClient>> more;
    for (int i = 1; i < 8; ++i) {
      more.push_back(std::make_unique<StreamClient>(port, kOther.substr(0, 31) + std::to_string(i), "", 0));
      CHECK(more.back()->status() == 200);
    }
    StreamClient ninth(port, kOther, "", 0);
    CHECK(ninth.status() == 400);
  }
  // After all that, the stream still answers its page.
  REQUIRE(PostInput(port, kName, "input=1&angle=45") == 204);
  StreamRecord r = NextFrame(stream);
  while (r.kind == "PRTF" && r.input != 1) r = NextFrame(stream);
  CHECK(r.input == 1);
}

TEST_CASE("prt view's stream: a page that stops reading frees its thread and stalls no other; one that reconnects goes on") {
  const std::string dir = ScratchDir("view_stream_stalls");
  std::vector<std::string> args = SmallViewArgs(dir);
  args[7] = "1024x768";  // --size: 3 MB frames, more than the sockets' buffers hold
  ViewProcess view(args, dir + "/stderr.txt");
  const int port = view.port();

  // A page that never reads, though it says it has shown every frame: the server draws and
  // writes until the socket's buffers are full, then its write times out (5 s).
  StreamClient stalled(port, kName, "ssaa=1", 1);
  REQUIRE(stalled.status() == 200);
  const auto start = std::chrono::steady_clock::now();
  for (int input = 2; input < 12; ++input)
    REQUIRE(PostInput(port, kName, "shown=1000000&input=" + std::to_string(input) + "&angle=" + std::to_string(input)) == 204);
  // Meanwhile another page's stream and the plain requests are served.
  {
    StreamClient other(port, kOther, "size=64x48", 1);
    REQUIRE(other.status() == 200);
    const StreamRecord r = NextFrame(other);
    CHECK(r.kind == "PRTF");
    CHECK(r.width == 64);
  }
  CHECK(Request(port, "/state").status == 200);
  CHECK(Request(port, "/frame?size=64x48").status == 200);
  CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(4));
  // The stalled stream is dropped once a write has waited the write timeout (5 s): forgotten
  // (its name unknown to /input) well within 20 s, without a byte read from it.
  bool forgotten = false;
  while (!forgotten && std::chrono::steady_clock::now() - start < std::chrono::seconds(20)) {
    forgotten = PostInput(port, kName, "shown=1") == 404;
    if (!forgotten) std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  CHECK(forgotten);
  CHECK(std::chrono::steady_clock::now() - start > std::chrono::seconds(4));  // not before its timeout

  // A page that reconnects under its name replaces its old stream, which ends.
  StreamClient first(port, kName, "size=64x48", 1);
  REQUIRE(first.status() == 200);
  CHECK(NextFrame(first).kind == "PRTF");
  StreamClient again(port, kName, "size=64x48&angle=10", 1);
  REQUIRE(again.status() == 200);
  CHECK(NextFrame(again).kind == "PRTF");
  // Its frames already sent may still come, then the end: within a few seconds (a stream left
  // running would send a keep-alive every 2 s for ever).
  const auto replaced_at = std::chrono::steady_clock::now();
  while (!first.Ended() && std::chrono::steady_clock::now() - replaced_at < std::chrono::seconds(5)) first.Next(1.0);
  CHECK(first.Ended());
  REQUIRE(PostInput(port, kName, "shown=1&input=2&size=64x48&angle=20") == 204);
  StreamRecord r = NextFrame(again);
  while (r.kind == "PRTF" && r.input != 2) r = NextFrame(again);
  CHECK(r.input == 2);
}

}  // TEST_SUITE

}  // namespace prt::test
