// Progress as a user at a terminal sees it: the binary runs on a pseudo-terminal (util-linux's
// `script`, part of every Debian system) with PRT_PROGRESS_DELAY=0, so that bars of short work
// show (by default a bar waits a second). A render shows the estimated time left; loading an
// OBJ shows its own bar; off a terminal, or with --quiet, nothing is drawn.
#include <doctest/doctest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/atomic_file.h"
#include "tests/test_process.h"

namespace prt {
namespace {

using test::Q;

/// What `prt arguments` writes to the terminal (stdout and stderr together, as `script` records
/// them), run with PRT_PROGRESS_DELAY=`delay`.
std::string OnTerminal(const std::string& arguments, const std::string& dir, const std::string& delay = "0") {
  const std::string inner = "PRT_PROGRESS_DELAY=" + Q(delay) + " " + Q(test::PrtBinary()) + " " + arguments;
  // `script -qec CMD FILE` runs CMD on a new pseudo-terminal and copies what it prints to FILE.
  const auto r = test::RunCommand("script -qec " + Q(inner) + " " + Q(dir + "/typescript"));
  CHECK(r.exit_code == 0);
  return ReadFile(dir + "/typescript");
}

/// A flat grid of n x n vertices as OBJ text: about 70 bytes a vertex with its two triangles.
std::string GridObj(int n) {
  std::string text;
  char line[96];
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      std::snprintf(line, sizeof line, "v %.4f 0 %.4f\n", 0.01 * i, 0.01 * j);
      text += line;
    }
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j + 1 < n; ++j) {
      const int a = i * n + j + 1;
      std::snprintf(line, sizeof line, "f %d %d %d\nf %d %d %d\n", a, a + 1, a + n, a + 1, a + n + 1, a + n);
      text += line;
    }
  return text;
}

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("progress: on a terminal a render shows the time left and an OBJ its loading") {
    REQUIRE(std::system("command -v script >/dev/null") == 0);  // util-linux: always on Debian
    const std::string dir = test::ScratchDir("progress_bar");
    const std::string long_render = " --frames 20 --size 160x120";
    const std::string render = OnTerminal(
        "render --transport unshadowed" + long_render + " --threads 1 --cache none --out " + Q(dir + "/frames"), dir);
    CAPTURE(render);
    CHECK(render.find("rendering [") != std::string::npos);
    CHECK(render.find(" s left") != std::string::npos);

    WriteFileAtomic(dir + "/grid.obj", GridObj(200));  // 2.7 MB
    const std::string load = OnTerminal("render --mesh " + Q(dir + "/grid.obj") +
                                            " --transport unshadowed --frames 1 --size 32x24 --cache none --out " +
                                            Q(dir + "/grid"),
                                        dir);
    CAPTURE(load);
    CHECK(load.find("loading grid.obj [") != std::string::npos);

    // A value that is not a delay is said (the bar then waits the usual second).
    const std::string bad = OnTerminal("render --transport unshadowed --frames 2 --size 32x24 --cache none --out " +
                                           Q(dir + "/bad"),
                                       dir, "abc");
    CHECK(bad.find("PRT_PROGRESS_DELAY='abc' is not a number of seconds from 0 to 3600") != std::string::npos);

    const std::string quiet = OnTerminal(
        "render --transport unshadowed --frames 20 --size 64x48 --cache none --quiet --out " + Q(dir + "/quiet"), dir);
    CHECK(quiet.find("rendering [") == std::string::npos);
    // Off a terminal (what RunPrt gives: stderr is a file) no bar is drawn either.
    const auto piped = test::RunCommand("PRT_PROGRESS_DELAY=0 " + Q(test::PrtBinary()) +
                                        " render --transport unshadowed" + long_render +
                                        " --threads 1 --cache none --out " + Q(dir + "/piped"));
    CHECK(piped.exit_code == 0);
    CHECK(piped.err.find("rendering [") == std::string::npos);
  }
}

}  // namespace prt
