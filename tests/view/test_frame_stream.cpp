// The frame stream's rules (src/view/frame_stream.h) without a server, and its records' bytes
// (src/view/stream_record.h) as the page reads them.
#include <doctest/doctest.h>

#include <chrono>
#include <future>
#include <thread>
#include <string>

#include "view/frame_stream.h"
#include "view/stream_record.h"

namespace prt {
namespace {

using Clock = std::chrono::steady_clock;

FrameRequest Turned(double degrees) {
  FrameRequest r;
  r.draw.start_degrees = degrees;
  return r;
}

/// Next on another thread, so that a test can check it is still waiting.
std::future<FrameStream::Step> NextLater(FrameStream& s, FrameStream::Job& job) {
  return std::async(std::launch::async, [&s, &job] { return s.Next(job); });
}

/// True when `f` has not finished within `ms`.
bool StillWaiting(std::future<FrameStream::Step>& f, int ms) {
  return f.wait_for(std::chrono::milliseconds(ms)) == std::future_status::timeout;
}

std::uint32_t Field(const std::string& s, std::size_t at) {
  std::uint32_t v = 0;
  for (int b = 3; b >= 0; --b) v = (v << 8) | static_cast<unsigned char>(s[at + b]);
  return v;
}

}  // namespace

TEST_SUITE("view") {

TEST_CASE("frame stream: an input drawn at once at interactive quality, its still frame once it has stayed kStillDelay") {
  const auto t0 = Clock::now();
  FrameStream s(Turned(10), 1);
  FrameStream::Job job;
  REQUIRE(s.Next(job) == FrameStream::Step::kDraw);
  CHECK(job.request.interactive);
  CHECK(job.input == 1);
  CHECK(job.frame == 1);
  CHECK(job.request.draw.start_degrees == 10.0);
  REQUIRE(s.Next(job) == FrameStream::Step::kDraw);
  CHECK(Clock::now() - t0 >= kStillDelay);
  CHECK_FALSE(job.request.interactive);
  CHECK(job.input == 1);
  CHECK(job.frame == 2);
  // Drawn once: nothing more until the page wants something new (and has room: it shows 2).
  s.Shown(2);
  auto next = NextLater(s, job);
  CHECK(StillWaiting(next, 300));
  s.Want(Turned(20), 2);
  REQUIRE(next.get() == FrameStream::Step::kDraw);
  CHECK(job.request.interactive);
  CHECK(job.input == 2);
  CHECK(job.request.draw.start_degrees == 20.0);
}

TEST_CASE("frame stream: inputs that keep coming get no still frame; the newest is drawn, older ones ignored") {
  FrameStream s(Turned(0), 1);
  FrameStream::Job job;
  REQUIRE(s.Next(job) == FrameStream::Step::kDraw);
  s.Shown(job.frame);
  for (int i = 2; i <= 6; ++i) {
    std::this_thread::sleep_for(kStillDelay / 3);
    s.Want(Turned(i), static_cast<std::uint64_t>(i));
  }
  s.Want(Turned(99), 3);  // overtaken: ignored
  REQUIRE(s.Next(job) == FrameStream::Step::kDraw);
  CHECK(job.request.interactive);  // not input 1's still frame, though kStillDelay has passed since it
  CHECK(job.input == 6);
  CHECK(job.request.draw.start_degrees == 6.0);
  CHECK(job.frame == 2);
}

TEST_CASE("frame stream: at most kFramesInFlight frames sent and not shown; Shown past the frames sent opens no more") {
  FrameStream s(Turned(0), 1);
  FrameStream::Job job;
  for (std::uint64_t i = 1; i <= kFramesInFlight; ++i) {
    s.Want(Turned(double(i)), i + 1);
    REQUIRE(s.Next(job) == FrameStream::Step::kDraw);
  }
  s.Want(Turned(50), 50);
  auto next = NextLater(s, job);
  CHECK(StillWaiting(next, 300));  // the window is full
  s.Shown(1);
  REQUIRE(next.get() == FrameStream::Step::kDraw);
  CHECK(job.input == 50);
  CHECK(job.frame == kFramesInFlight + 1);
  // A page that says it has shown frames never sent: the count stops at those sent.
  s.Shown(1000);
  s.Want(Turned(60), 60);
  REQUIRE(s.Next(job) == FrameStream::Step::kDraw);
  s.Want(Turned(61), 61);
  REQUIRE(s.Next(job) == FrameStream::Step::kDraw);
  s.Want(Turned(62), 62);
  auto full = NextLater(s, job);
  CHECK(StillWaiting(full, 300));
  s.Stop();
  CHECK(full.get() == FrameStream::Step::kStopped);
}

TEST_CASE("frame stream: Stop wakes a waiting Next and every later one; silence gives a keep-alive") {
  FrameStream s(Turned(0), 1);
  FrameStream::Job job;
  REQUIRE(s.Next(job) == FrameStream::Step::kDraw);
  REQUIRE(s.Next(job) == FrameStream::Step::kDraw);  // the still frame
  const auto t0 = Clock::now();
  CHECK(s.Next(job) == FrameStream::Step::kKeepAlive);
  CHECK(Clock::now() - t0 >= kKeepAliveAfter);  // not before the silence (an order, not a speed)
  auto waiting = NextLater(s, job);
  CHECK(StillWaiting(waiting, 100));
  s.Stop();
  // Woken by Stop: it returns well before its own keep-alive would have come (an order of events;
  // the wait bounds only a Next that Stop did not wake).
  CHECK(waiting.wait_for(kKeepAliveAfter / 2) == std::future_status::ready);
  CHECK(waiting.get() == FrameStream::Step::kStopped);
  CHECK(s.Stopped());
  s.Want(Turned(5), 5);
  CHECK(s.Next(job) == FrameStream::Step::kStopped);
}

TEST_CASE("frame stream: a page silent for its silence limit with its window full ends its stream; one that answers does not") {
  constexpr std::chrono::milliseconds kSilence{400};
  FrameStream s(Turned(0), 1, kSilence);
  FrameStream::Job job;
  REQUIRE(s.Next(job) == FrameStream::Step::kDraw);
  REQUIRE(s.Next(job) == FrameStream::Step::kDraw);  // the still frame: the window is full
  const auto full = Clock::now();
  CHECK(s.Next(job) == FrameStream::Step::kStopped);
  CHECK(Clock::now() - full >= kSilence - std::chrono::milliseconds(150));  // counted from the last word
  CHECK(s.Stopped());

  // A page that keeps answering within the limit keeps its stream, its window full all along
  // (it says it has shown the same frame again: heard, though nothing moves).
  FrameStream answered(Turned(0), 1, kSilence);
  REQUIRE(answered.Next(job) == FrameStream::Step::kDraw);
  REQUIRE(answered.Next(job) == FrameStream::Step::kDraw);  // the still frame: the window is full
  FrameStream::Job later;
  auto waiting = NextLater(answered, later);
  for (int i = 0; i < 6; ++i) {  // 1.2 s: three limits' worth of time, each part answered in time
    std::this_thread::sleep_for(kSilence / 2);
    answered.Shown(0);
  }
  CHECK(StillWaiting(waiting, 0));  // neither ended nor drawing
  answered.Stop();
  CHECK(waiting.get() == FrameStream::Step::kStopped);

  // One whose window has room may say nothing for longer than the limit: it only gets keep-alives.
  FrameStream roomy(Turned(0), 1, kSilence);
  REQUIRE(roomy.Next(job) == FrameStream::Step::kDraw);
  roomy.Shown(job.frame);
  REQUIRE(roomy.Next(job) == FrameStream::Step::kDraw);  // the still frame: one in flight
  const auto idle = Clock::now();
  CHECK(roomy.Next(job) == FrameStream::Step::kKeepAlive);  // 2 s without a word: not dropped
  CHECK(Clock::now() - idle >= kKeepAliveAfter);
  CHECK_FALSE(roomy.Stopped());
}

TEST_CASE("stream records: a frame's header fields little-endian, its pixels RGBA and opaque; errors and keep-alives") {
  Image8 image(3, 2);
  for (std::size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = static_cast<std::uint8_t>(10 + i);
  const std::string f = FrameRecord(image, 0x01020304u, 7, 12.3456, true);
  REQUIRE(f.size() == kStreamHeaderBytes + 3 * 2 * 4);
  CHECK(f.substr(0, 4) == "PRTF");
  CHECK(f[4] == 0x04);  // little-endian
  CHECK(Field(f, 4) == 0x01020304u);
  CHECK(Field(f, 8) == 7u);
  CHECK(Field(f, 12) == 3u);
  CHECK(Field(f, 16) == 2u);
  CHECK(Field(f, 20) == 12346u);  // microseconds
  CHECK(Field(f, 24) == kStillFlag);
  CHECK(Field(f, 28) == 0u);
  for (std::size_t p = 0; p < 6; ++p) {
    for (int c = 0; c < 3; ++c) CHECK(static_cast<unsigned char>(f[kStreamHeaderBytes + 4 * p + c]) == image.rgb[3 * p + c]);
    CHECK(static_cast<unsigned char>(f[kStreamHeaderBytes + 4 * p + 3]) == 255);
  }
  CHECK(Field(FrameRecord(image, 1, 1, 0.0, false), 24) == 0u);

  const std::string e = ErrorRecord(5, 6, "sh interreflection: still computing");
  CHECK(e.substr(0, 4) == "PRTE");
  CHECK(Field(e, 4) == 5u);
  CHECK(Field(e, 8) == 6u);
  CHECK(Field(e, 12) == 35u);
  CHECK(e.substr(kStreamHeaderBytes) == "sh interreflection: still computing");
  const std::string k = KeepAliveRecord();
  CHECK(k == std::string("PRTK") + std::string(28, '\0'));
}

}  // TEST_SUITE

}  // namespace prt
