// `prt view` as a user's browser and an attacker's page meet it, without a browser: what it
// serves and refuses, that its frames are the frames its render command line draws, that a
// stalled or vanished client stalls no one, and that SIGTERM and SIGINT end it cleanly.
#include <cctype>
#include <chrono>
#include <csignal>
#include <sstream>
#include <thread>
#include <utility>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/atomic_file.h"
#include "io/png_io.h"
#include "tests/test_process.h"
#include "tests/view/view_process.h"
#include "view/request_guard.h"

namespace fs = std::filesystem;

namespace prt::test {
namespace {

/// Two frames of the same transport, light and camera differ at most this much per channel:
/// the page's frame and prt render's are drawn by the same code from the same numbers (the
/// camera's floats travel through the command line as 9 significant digits, which read back
/// exactly): none.
constexpr int kSameFrame = 0;

/// The /command line for `query` run with the test's binary into `out`; its frame 0.
Image8 RenderCommand(int port, const std::string& query, const std::string& out) {
  const HttpReply command = Request(port, "/command?" + query);
  REQUIRE(command.status == 200);
  std::string line = command.body;
  while (!line.empty() && line.back() == '\n') line.pop_back();
  REQUIRE(line.rfind("prt render ", 0) == 0);
  CHECK(line.find(" --out out/view ") != std::string::npos);
  // Every vertex takes the page's directions (256), those the camera sees and the others, whose
  // bounces reach the seen ones.
  if (query.find("basis=wavelet") == std::string::npos && query.find("mode=unshadowed") == std::string::npos)
    CHECK(line.find(" --samples 256 --hidden-samples 256 ") != std::string::npos);
  // Into the test's folder, one frame: the frame the page showed is frame 0.
  line = line.substr(4) ;
  line = line.substr(0, line.find(" --out out/view")) + " --out " + Q(out) + " --frames 1 --quiet";
  const RunResult r = RunPrt(line);
  INFO(line, "\n", r.err);
  REQUIRE(r.exit_code == 0);
  return ReadPng(out + "/frame_0000.png");
}

int MaxDifference(const Image8& a, const Image8& b) {
  REQUIRE(a.width == b.width);
  REQUIRE(a.height == b.height);
  int most = 0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) most = std::max(most, std::abs(int(a.rgb[i]) - int(b.rgb[i])));
  return most;
}

Image8 FramePng(int port, const std::string& query, const std::string& dir, const std::string& name) {
  const HttpReply png = Request(port, "/frame.png?" + query);
  REQUIRE(png.status == 200);
  CHECK(png.Header("Content-Type") == "image/png");
  const std::string path = dir + "/" + name;
  WriteFileAtomic(path, png.body);
  return ReadPng(path);
}

}  // namespace

TEST_SUITE("view") {

TEST_CASE("prt view serves its page, its state and frames, and refuses everything else with a 4xx, going on") {
  const std::string dir = ScratchDir("view_refusals");
  ViewProcess view(SmallViewArgs(dir), dir + "/stderr.txt");
  const int port = view.port();
  const std::string host = "127.0.0.1:" + std::to_string(port);

  const HttpReply page = Request(port, "/");
  CHECK(page.status == 200);
  CHECK(page.Header("Content-Type") == "text/html; charset=utf-8");
  CHECK(page.body.find("<script src=\"view.js\">") != std::string::npos);
  const HttpReply script = Request(port, "/view.js");
  CHECK(script.status == 200);
  CHECK(script.body.find("window.prtView") != std::string::npos);
  const HttpReply state = Request(port, "/state");
  CHECK(state.status == 200);
  CHECK(state.Header("Content-Type") == "application/json");
  CHECK(state.body.find("\"lmax\":3") != std::string::npos);
  const HttpReply frame = Request(port, "/frame");
  CHECK(frame.status == 200);
  CHECK(frame.Header("X-Prt-Size") == "160x120");
  CHECK(frame.Header("Content-Type") == "application/octet-stream");
  CHECK(script.Header("Content-Type") == "text/javascript; charset=utf-8");
  CHECK(Request(port, "/command").Header("Content-Type") == "text/plain; charset=utf-8");
  CHECK(frame.body.size() == 160u * 120u * 3u);

  // Never a file from disk, whatever the path says.
  for (const std::string path : {"/CMakeLists.txt", "/../CMakeLists.txt", "/%2e%2e/CMakeLists.txt", "/etc/passwd",
                                 "/src/view/page/index.html", "/index.htm", "/view.js.map", "/page/view.js"}) {
    INFO(path);
    CHECK(Request(port, path).status == 404);
  }
  // Parameters out of range, unknown, twice, or unparsable: 400 naming the parameter.
  const std::pair<const char*, const char*> bad[] = {
      {"lmax=4", "lmax=4"},           {"lmax=-1", "lmax"},          {"size=100000x10", "size"},
      {"size=0x8", "size"},           {"angle=nan", "angle"},       {"axis=0,0,0", "axis"},
      {"axis=1,2", "axis"},           {"view=transport:16", "view"}, {"view=lite", "view"},
      {"env=1", "env"},               {"mode=smooth", "mode"},      {"basis=pca", "basis"},
      {"exposure=21", "exposure"},    {"fov=180", "fov"},           {"ssaa=9", "ssaa"},
      {"tonemap=filmic", "tonemap"},  {"colour=red", "colour"},     {"lmax=1&lmax=2", "lmax"},
      {"eye=1,1,1&target=1,1,1", "eye"}};
  for (const auto& [query, named] : bad) {
    INFO(query);
    const HttpReply r = Request(port, std::string("/frame?") + query);
    CHECK(r.status == 400);
    CHECK(r.body.find(named) != std::string::npos);
    CHECK(Request(port, std::string("/command?") + query).status == 400);
  }
  // A transport not computed: 409 until POST /compute.
  CHECK(Request(port, "/frame?mode=interreflection").status == 409);

  // DNS rebinding and other sites.
  const std::string origin = "Origin: http://" + host + "\r\n";
  CHECK(SendRaw(port, "GET / HTTP/1.1\r\nHost: evil.example:" + std::to_string(port) + "\r\nConnection: close\r\n\r\n")
            .status == 403);
  CHECK(SendRaw(port, "GET /frame HTTP/1.1\r\nConnection: close\r\n\r\n").status == 403);  // no Host
  CHECK(SendRaw(port, "GET / HTTP/1.1\r\nHost: 127.0.0.1:1\r\nConnection: close\r\n\r\n").status == 403);
  CHECK(Request(port, "/frame", "GET", "Origin: http://evil.example\r\n").status == 403);
  CHECK(Request(port, "/state", "GET", "Sec-Fetch-Site: cross-site\r\n").status == 403);
  CHECK(Request(port, "/compute?mode=unshadowed", "POST").status == 403);  // state changed, no Origin
  CHECK(Request(port, "/compute?mode=unshadowed", "POST", "Origin: http://evil.example\r\n").status == 403);
  CHECK(Request(port, "/compute?mode=unshadowed", "POST", "Origin: http://localhost.evil.example:" +
                std::to_string(port) + "\r\n").status == 403);
  // Methods, bodies, malformed and oversized requests.
  CHECK(Request(port, "/", "PUT", origin).status == 405);
  CHECK(Request(port, "/frame", "DELETE", origin).status == 405);
  CHECK(Request(port, "/state", "POST", origin).status == 405);
  CHECK(Request(port, "/compute?mode=unshadowed", "POST", origin, std::string(4096, 'x')).status == 413);
  CHECK(Request(port, "/compute?colour=red", "POST", origin).status == 400);
  CHECK(Request(port, "/compute?mode=smooth", "POST", origin).status == 400);
  CHECK(Request(port, "/frame?angle=" + std::string(20000, '1')).status == 414);
  const int garbage = SendRaw(port, "THIS IS NOT HTTP\r\n\r\n").status;
  CHECK(garbage >= 400);
  CHECK(garbage < 500);
  CHECK(SendRaw(port, "GET / HTTP/1.1\r\nHost: " + host + "\r\nX-Big: " + std::string(20000, 'a') +
                          "\r\nConnection: close\r\n\r\n").status != 200);

  // After all of that it still serves, and nothing it refused changed its state.
  CHECK(Request(port, "/frame").body == frame.body);
  CHECK(Request(port, "/state").body.find("\"key\":\"sh unshadowed\"") == std::string::npos);
}

TEST_CASE("prt view's frames are the frames of the prt render command line it gives, for any turn, lmax, env and mode") {
  const std::string dir = ScratchDir("view_command");
  std::vector<std::string> args = SmallViewArgs(dir);
  args.push_back("sky:sun=40");  // a second environment to switch to
  ViewProcess view(args, dir + "/stderr.txt");
  const int port = view.port();
  const std::string origin = "Origin: http://127.0.0.1:" + std::to_string(port) + "\r\n";

  // A slow turn about a tilted axis at a lower lmax, under the second environment, and a
  // camera moved: each what `prt render` draws from the line the page gives.
  const std::string queries[] = {
      "lmax=3",
      "axis=0.3,1,0.2&angle=37.5&lmax=1&env=1",
      "angle=3&lmax=2&eye=5,6,7&fov=30&view=irradiance&tonemap=reinhard&exposure=-0.5",
      "angle=200&view=transport:5",
      // The first case's setting about another axis: its kept frame light turned about it
      // (FrameLight::SetAxis), drawn as a light made with that axis (render's).
      "axis=1,1,0&angle=50"};
  int case_index = 0;
  std::vector<Image8> frames;
  for (const std::string& query : queries) {
    INFO(query);
    const std::string sub = dir + "/case" + std::to_string(case_index++);
    fs::create_directories(sub);
    const Image8 page = FramePng(port, query, sub, "page.png");
    // The raw frame the page draws is the PNG's pixels.
    const HttpReply raw = Request(port, "/frame?" + query);
    REQUIRE(raw.status == 200);
    CHECK(raw.body == std::string(page.rgb.begin(), page.rgb.end()));
    const Image8 render = RenderCommand(port, query, sub + "/render");
    CHECK(MaxDifference(page, render) <= kSameFrame);
    frames.push_back(page);
  }
  // The turn, the lmax and the env each change the picture.
  CHECK(MaxDifference(frames[0], frames[1]) > 20);

  // lmax 1 is what prt render --lmax 1 draws, and not lmax 3's picture.
  {
    const Image8 low = FramePng(port, "lmax=1", dir, "lmax1.png");
    CHECK(MaxDifference(low, frames[0]) > 5);
    fs::create_directories(dir + "/lmax1");
    CHECK(MaxDifference(low, RenderCommand(port, "lmax=1", dir + "/lmax1")) <= kSameFrame);
  }

  // The wavelet basis, all its light terms and eight of them: render's pictures, and not the same.
  REQUIRE(Request(port, "/compute?basis=wavelet&mode=shadowed", "POST", origin).status == 202);
  WaitReady(port, "wavelet shadowed");
  // The last: the first's setting about another axis (its kept light turned by SetAxis).
  for (const std::string terms : {"0", "8", "0&axis=1,1,0"}) {
    const std::string query = "basis=wavelet&angle=25&terms=" + terms + (terms == "8" ? "&env=1" : "");
    const std::string name = "wavelet" + terms.substr(0, 1) + (terms.size() > 1 ? "tilted" : "");
    INFO(query);
    fs::create_directories(dir + "/" + name);
    const Image8 page = FramePng(port, query, dir, name + ".png");
    CHECK(MaxDifference(page, RenderCommand(port, query, dir + "/" + name)) <= kSameFrame);
  }
  CHECK(MaxDifference(ReadPng(dir + "/wavelet0.png"), ReadPng(dir + "/wavelet8.png")) > 5);

  // Another mode: computed on request, then its frames are render's in that mode.
  REQUIRE(Request(port, "/compute?basis=sh&mode=unshadowed", "POST", origin).status == 202);
  WaitReady(port, "sh unshadowed");
  fs::create_directories(dir + "/unshadowed");
  const Image8 unshadowed = FramePng(port, "mode=unshadowed&angle=90", dir, "unshadowed.png");
  CHECK(MaxDifference(unshadowed, RenderCommand(port, "mode=unshadowed&angle=90", dir + "/unshadowed")) <= kSameFrame);
  CHECK(MaxDifference(unshadowed, FramePng(port, "angle=90", dir, "shadowed.png")) > 5);
  REQUIRE(Request(port, "/compute?basis=sh&mode=interreflection", "POST", origin).status == 202);
  WaitReady(port, "sh interreflection");
  fs::create_directories(dir + "/bounced");
  const Image8 bounced = FramePng(port, "mode=interreflection&angle=60", dir, "bounced.png");
  CHECK(MaxDifference(bounced, RenderCommand(port, "mode=interreflection&angle=60", dir + "/bounced")) <= kSameFrame);
}

/// The number after `"name":` in a flat JSON object.
double JsonNumber(const std::string& json, const std::string& name) {
  const std::size_t at = json.find("\"" + name + "\":");
  REQUIRE(at != std::string::npos);
  return std::stod(json.substr(at + name.size() + 3));
}

TEST_CASE("prt view's error figures: each setting against the prt reference it measures when asked") {
  const std::string dir = ScratchDir("view_error");
  std::vector<std::string> args = SmallViewArgs(dir);
  args.insert(args.end(), {"--reference-samples", "512"});
  ViewProcess view(args, dir + "/stderr.txt");
  const int port = view.port();
  const std::string origin = "Origin: http://127.0.0.1:" + std::to_string(port) + "\r\n";
  CHECK(Request(port, "/error?lmax=2").status == 409);  // not measured yet
  REQUIRE(Request(port, "/reference?mode=shadowed&env=0", "POST", origin).status == 202);
  CHECK(Request(port, "/reference?mode=shadowed&lmax=1", "POST", origin).status == 400);
  HttpReply reply;
  for (int i = 0; i < 3000 && (reply = Request(port, "/error?lmax=0")).status == 409; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  REQUIRE(reply.status == 200);
  CHECK(reply.Header("Content-Type") == "application/json");
  // More bands, less error (measured 43 %, 20 %, 16 %, 13 % under the sky's sun): the figure
  // follows the setting, not the frame.
  double last = 2.0;
  for (int lmax = 0; lmax <= 3; ++lmax) {
    const HttpReply e = Request(port, "/error?lmax=" + std::to_string(lmax) + "&angle=" + std::to_string(30 * lmax));
    REQUIRE(e.status == 200);
    const double error = JsonNumber(e.body, "error");
    CHECK(error < last);
    CHECK(JsonNumber(e.body, "lmax") == lmax);
    last = error;
  }
  CHECK(last > 0.05);  // SH at lmax 3 blurs the sun's shadow
  // Wavelets keep the shadow: a tenth of SH's error here (measured 1.4 % against 13 %).
  REQUIRE(Request(port, "/compute?basis=wavelet&mode=shadowed", "POST", origin).status == 202);
  WaitReady(port, "wavelet shadowed");
  const double wavelet = JsonNumber(Request(port, "/error?basis=wavelet").body, "error");
  CHECK(wavelet < last / 4);
  // Fewer of the light's wavelet terms, more error: the figure is the setting's.
  const double few = JsonNumber(Request(port, "/error?basis=wavelet&terms=8").body, "error");
  CHECK(few > 1.5 * wavelet);
  // The reference is prt reference's at the same directions: its own error as that command says.
  const HttpReply e = Request(port, "/error?lmax=3");
  const RunResult ref = RunPrt("reference --mesh " + Q(args[1]) + " --reference-samples 512 --size 32x24 --out " +
                               Q(dir + "/reference"));
  REQUIRE(ref.exit_code == 0);
  const std::size_t at = ref.err.find("% of the RMS radiance");
  REQUIRE(at != std::string::npos);
  const std::size_t open = ref.err.rfind('(', at);
  CHECK(std::stod(ref.err.substr(open + 1)) == doctest::Approx(100.0 * JsonNumber(e.body, "reference_error")).epsilon(2e-3));
  // The command line of a view given --reference-samples runs (render has no such option).
  fs::create_directories(dir + "/command");
  CHECK(MaxDifference(FramePng(port, "lmax=2", dir, "lmax2.png"), RenderCommand(port, "lmax=2", dir + "/command")) <=
        kSameFrame);
  // Another mode's reference is its own.
  CHECK(Request(port, "/error?mode=unshadowed").status == 409);
}

TEST_CASE("prt view: a client that stalls or vanishes mid-frame stalls no other, and the server goes on") {
  const std::string dir = ScratchDir("view_stalls");
  std::vector<std::string> args = SmallViewArgs(dir);
  args[7] = "1024x768";  // --size: a frame that takes a while to send
  ViewProcess view(args, dir + "/stderr.txt");
  const int port = view.port();
  const std::string host = "Host: 127.0.0.1:" + std::to_string(port) + "\r\n";
  // Three stalled clients: half a request line, headers without their end, and a frame asked
  // for and never read (its 2.4 MB fill the socket's buffers).
  const int half = Connect(port);
  REQUIRE(::send(half, "GET /fra", 8, MSG_NOSIGNAL) == 8);
  const int headers = Connect(port);
  const std::string partial = "GET /frame HTTP/1.1\r\n" + host;
  REQUIRE(::send(headers, partial.data(), partial.size(), MSG_NOSIGNAL) == ssize_t(partial.size()));
  const int unread = Connect(port);
  const std::string whole = "GET /frame?angle=10 HTTP/1.1\r\n" + host + "\r\n";
  REQUIRE(::send(unread, whole.data(), whole.size(), MSG_NOSIGNAL) == ssize_t(whole.size()));
  // Clients that vanish mid-frame: the request sent, the connection closed at once.
  for (int i = 0; i < 4; ++i) {
    const int gone = Connect(port);
    const std::string ask =
        "GET /frame?size=64x48&angle=" + std::to_string(20 + i) + " HTTP/1.1\r\n" + host + "\r\n";
    REQUIRE(::send(gone, ask.data(), ask.size(), MSG_NOSIGNAL) == ssize_t(ask.size()));
    ::close(gone);
  }
  // Meanwhile others are served, before any stalled client's timeout: the stalled connections
  // are all still open once they have been.
  for (int i = 0; i < 3; ++i) {
    const HttpReply r = Request(port, "/frame?size=64x48&ssaa=1&angle=" + std::to_string(40 + i));
    CHECK(r.status == 200);
    CHECK(r.body.size() == 64u * 48u * 3u);
  }
  CHECK(Request(port, "/state").status == 200);
  CHECK(StillOpen(half));
  CHECK(StillOpen(headers));
  ::close(half);
  ::close(headers);
  ::close(unread);
  CHECK(Request(port, "/frame").status == 200);
  CHECK(::kill(view.pid(), 0) == 0);  // still running
}

TEST_CASE("prt view: more stalled clients than a small pool has threads stall no one, and each is dropped in seconds") {
  const std::string dir = ScratchDir("view_many_stalls");
  ViewProcess view(SmallViewArgs(dir), dir + "/stderr.txt");
  const int port = view.port();
  // Twelve connections, each with half a request line, then nothing.
  std::vector<int> stalled;
  for (int i = 0; i < 12; ++i) {
    const int fd = Connect(port);
    REQUIRE(::send(fd, "GET /sta", 8, MSG_NOSIGNAL) == 8);
    stalled.push_back(fd);
  }
  const auto start = std::chrono::steady_clock::now();
  CHECK(Request(port, "/state").status == 200);
  // Served while every stalled connection is still open: not by waiting for their timeouts,
  // and they were not refused at once either.
  for (const int fd : stalled) CHECK(StillOpen(fd));
  // The server answers each stalled connection 408 and closes it once its request's deadline
  // (5 s) has passed: the answer, then a recv that returns 0 (closed), well before the 20 s
  // this waits for all of them together (a timeout of minutes would not be).
  const auto deadline = start + std::chrono::seconds(20);
  for (const int fd : stalled) {
    std::string answer;
    bool closed = false;
    for (;;) {
      pollfd p{fd, POLLIN, 0};
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
      if (::poll(&p, 1, static_cast<int>(std::max<long>(0, left.count()))) != 1) break;
      char buffer[512];
      const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
      if (n <= 0) {
        closed = true;
        break;
      }
      answer.append(buffer, static_cast<std::size_t>(n));
    }
    CHECK(closed);
    CHECK(answer.rfind("HTTP/1.1 408", 0) == 0);
    ::close(fd);
  }
}

TEST_CASE("prt view ends cleanly on SIGTERM and SIGINT, leaving only the cache it completed") {
  for (const int sig : {SIGTERM, SIGINT}) {
    INFO(sig);
    const std::string dir = ScratchDir("view_signal_" + std::to_string(sig));
    std::vector<std::string> args = SmallViewArgs(dir);
    args.insert(args.end(), {"--cache", dir + "/view.cache"});
    const std::set<std::string> before = [&dir] {
      std::set<std::string> names;
      for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
      return names;
    }();
    ViewProcess view(args, dir + "/../view_signal_stderr.txt");
    const int port = view.port();
    // A background transport under way, and frames served, when the signal comes.
    REQUIRE(Request(port, "/compute?mode=interreflection", "POST",
                    "Origin: http://127.0.0.1:" + std::to_string(port) + "\r\n").status == 202);
    CHECK(Request(port, "/frame").status == 200);
    const int status = view.Stop(sig);
    CHECK(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == sig);
    std::set<std::string> after;
    for (const auto& e : fs::directory_iterator(dir)) after.insert(e.path().filename().string());
    std::set<std::string> expected = before;
    expected.insert("view.cache");
    CHECK(after == expected);
    // The cache is whole: a second view reads it instead of computing.
    ViewProcess again(args, dir + "/../view_signal_again.txt");
    again.Stop(SIGTERM);
    std::ifstream log(dir + "/../view_signal_again.txt");
    const std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
    CHECK(text.find("cache") != std::string::npos);
    CHECK(text.find("transport: taken from the cache") != std::string::npos);
  }
}

TEST_CASE("prt view listens before its first transport: the page at once with the progress, a taken port refused first") {
  const std::string dir = ScratchDir("view_starting");
  // The embedded demo scene: its first transport takes seconds to minutes, time enough to look.
  ViewProcess view = ViewProcess::Starting({"--port", "0", "--size", "64x48"}, dir + "/stderr.txt");
  const int port = view.port();
  const HttpReply state = Request(port, "/state");
  CHECK(state.status == 200);
  CHECK(state.body.find("\"starting\":true") != std::string::npos);
  CHECK(state.body.find("\"progress\":{\"label\":") != std::string::npos);
  CHECK(Request(port, "/").status == 200);
  const HttpReply frame = Request(port, "/frame");
  CHECK(frame.status == 409);
  CHECK(frame.body.find("starting") != std::string::npos);
  CHECK(Request(port, "/stream?stream=0123456789abcdef", "GET", "X-Prt-Stream: 1\r\n").status == 409);
  CHECK(Request(port, "/command").status == 409);
  // A second server on its port is refused at once, before its own transport: a clear error, no
  // address printed, nothing computed.
  const auto start = std::chrono::steady_clock::now();
  const RunResult taken = RunCommand("timeout -s KILL 120 " + Q(PrtBinary()) + " view --port " + std::to_string(port));
  CHECK(taken.exit_code == 1);
  CHECK(taken.out.empty());
  CHECK(taken.err.find("--port " + std::to_string(port) + ": cannot listen there") != std::string::npos);
  CHECK(taken.err.find("transport:") == std::string::npos);
  CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(15));
  // Still starting (the demo's transport is not done), and SIGTERM ends it at once.
  CHECK(Request(port, "/state").body.find("\"starting\":true") != std::string::npos);
  const int status = view.Stop(SIGTERM);
  CHECK(WIFSIGNALED(status));
  CHECK(WTERMSIG(status) == SIGTERM);
}

TEST_CASE("prt view --bind: loopback names serve this machine only, a wildcard every address of it, each said") {
  const std::string dir = ScratchDir("view_bind");
  // The embedded demo scene, still starting: the summary's serving line comes first.
  const auto serving = [&](const std::string& bind) {
    const std::string log = dir + "/" + bind + ".txt";
    ViewProcess view = ViewProcess::Starting({"--port", "0", "--size", "64x48", "--bind", bind}, log);
    const int port = view.port();
    std::string line;
    for (std::istringstream in(ReadFile(log)); std::getline(in, line);)
      if (line.find("view: serving") != std::string::npos) break;
    return std::make_pair(std::move(view), line + " (port " + std::to_string(port) + ")");
  };
  {
    // A loopback name: no warning. (localhost may be ::1 first, which this test's client does
    // not reach: the summary alone, read from a run ended after its first seconds.)
    const RunResult local = RunCommand("timeout -s TERM 5 " + Q(PrtBinary()) + " view --port 0 --size 64x48 --bind localhost");
    INFO(local.err);
    CHECK(local.err.find("view: serving http://localhost:") != std::string::npos);
    CHECK(local.err.find("to this machine only") != std::string::npos);
    CHECK(local.err.find("any machine") == std::string::npos);
  }
  const auto [any, line] = serving("0.0.0.0");
  INFO(line);
  CHECK(any.address() == "http://127.0.0.1:" + std::to_string(any.port()) + "/");
  CHECK(line.find("any machine that reaches it may open the page") != std::string::npos);
  const MachineNames machine = ThisMachine();
  std::string name = machine.hostname;
  for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const std::string p = std::to_string(any.port());
  // Every name it answers under, listed one by one.
  CHECK(line.find(" as 127.0.0.1:" + p + ", localhost:" + p + ", ") != std::string::npos);
  CHECK(line.find(", " + name + ":" + p) != std::string::npos);
  // Answering under the machine's own name and each of its IPv4 addresses.
  const auto state = [&](const std::string& host) {
    return SendRaw(any.port(), "GET /state HTTP/1.1\r\nHost: " + host + ":" + std::to_string(any.port()) +
                                   "\r\nConnection: close\r\n\r\n").status;
  };
  CHECK(state("127.0.0.1") == 200);
  CHECK(state(machine.hostname) == 200);
  for (const std::string& address : machine.addresses)
    if (address.find(':') == std::string::npos) CHECK(state(address) == 200);
}

TEST_CASE("prt view: --port, --bind and its other options are checked before any work") {
  const std::string dir = ScratchDir("view_options");
  const std::string mesh = WriteSmallScene(dir);
  for (const std::string bad : {"--port 70000", "--port -1", "--port x", "--lmax 99", "--size 0x10",
                                 "--view transport:99", "--basis wavelet --view transport:1"}) {
    INFO(bad);
    const RunResult r = RunPrt("view --mesh " + Q(mesh) + " " + bad);
    CHECK(r.exit_code == 2);
    CHECK(r.err.rfind("prt: error: ", 0) == 0);
    CHECK(r.out.empty());
    CHECK(r.err.find("mesh:") == std::string::npos);  // refused before the mesh was loaded
  }
  // A port in use: a clear error, no address printed.
  ViewProcess first(SmallViewArgs(dir), dir + "/first.txt");
  const RunResult taken = RunCommand("timeout -s KILL 120 " + Q(PrtBinary()) + " view --mesh " + Q(mesh) +
                                     " --samples 64 --lmax 1 --port " + std::to_string(first.port()));
  CHECK(taken.exit_code == 1);
  CHECK(taken.out.empty());
  CHECK(taken.err.find("--port " + std::to_string(first.port()) + ": cannot listen there") != std::string::npos);
  CHECK(taken.err.find("transport:") == std::string::npos);  // refused before any transport
  // An unknown environment among the extra ones: refused before any transport.
  const RunResult env = RunPrt("view --mesh " + Q(mesh) + " --port 0 " + Q(dir + "/no-such.hdr"));
  CHECK(env.exit_code != 0);
  CHECK(env.err.find("no-such.hdr") != std::string::npos);
  CHECK(env.err.find("transport:") == std::string::npos);
}

}  // TEST_SUITE

}  // namespace prt::test
