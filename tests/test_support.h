#pragma once
/// \file
/// Helpers shared by the tests: where the shared course data is, scratch folders, and running the
/// `prt` binary the way a user does.

#include <doctest/doctest.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/image.h"
#include "core/parallel.h"

namespace prt::test {

/// The project's source folder (for fixtures in tests/data).
std::string SourceDir();
/// A fixture path: SourceDir()/tests/data/<relative>.
std::string Fixture(const std::string& relative);

/// `../shared/data` beside the project if it exists (a user's fresh clone does not have it), or
/// the folder $PRT_SHARED_DATA names (PRT_SHARED_DATA=none runs the suite as a fresh clone would).
std::optional<std::string> SharedData();

/// The decorator of a test case that needs `../shared/data`: `TEST_CASE("..." *
/// test::NeedsSharedData())` is skipped, and counted as skipped by the runner, when it is absent.
/// Inside such a test, SharedData() has a value.
doctest::skip NeedsSharedData();

/// Debian's ffmpeg program (with ffprobe beside it) if it is on PATH: the video tests need it
/// to encode .mp4 and .webm and to decode what prt writes with a standard decoder.
std::optional<std::string> Ffmpeg();

/// The decorator of a test case that needs Ffmpeg(): skipped, and counted as skipped by the
/// runner, without it (PRT_REQUIRE_FFMPEG=1, which CI sets, makes its absence an error).
doctest::skip NeedsFfmpeg();

/// Debian's cmark-gfm program (GitHub's own Markdown renderer) if it is on PATH: the report
/// tests render the Markdown tables prt writes with it (`cmark-gfm -e table`) and read the HTML.
std::optional<std::string> CmarkGfm();

/// The decorator of a test case that needs CmarkGfm(): skipped, and counted as skipped by the
/// runner, without it (PRT_REQUIRE_CMARK_GFM=1, which CI sets, makes its absence an error).
doctest::skip NeedsCmarkGfm();

/// Debian's chromium (and python3, which drives it over the DevTools Protocol: scripts/cdp.py)
/// if both are on PATH: the browser tests of `prt view` need them.
std::optional<std::string> Chromium();
/// The decorator of a test case that needs Chromium(): skipped, and counted as skipped by the
/// runner, without it (PRT_REQUIRE_CHROMIUM=1, which CI sets, makes its absence an error).
doctest::skip NeedsChromium();
/// The decorator of a test case that runs a whole `prt report` study end to end (minutes under a
/// sanitizer): `TEST_CASE("..." * test::WholeStudy())` puts it in the suite, and so the CTest
/// label, `report_study`. The unsanitized suite runs it; the ASan + UBSan pass leaves the label
/// out, and scripts/sanitize.sh says why.
doctest::test_suite WholeStudy();

/// The message of the prt::Error (core/error.h) that `run` throws; "" when it throws none.
std::string ErrorMessage(const std::function<void()>& run);

/// The `prt` binary the command-line tests run: $PRT_BINARY if set, else the one built beside
/// the tests (its path is compiled in, so the tests need no runner to find it).
std::string PrtBinary();

/// An empty scratch folder for one test, under the build folder's test-tmp/.
std::string ScratchDir(const std::string& name);

struct RunResult {
  int exit_code = -1;
  std::string out;  ///< stdout
  std::string err;  ///< stderr
};
/// `text` as one single-quoted shell word (a quote inside it included).
std::string ShellQuote(const std::string& text);

/// ShellQuote under a short name, for the paths in command lines: "render --out " + Q(dir).
inline std::string Q(const std::string& text) { return ShellQuote(text); }

/// Whether this test program is built under a sanitizer (scripts/sanitize.sh: ASan + UBSan, or
/// TSan). The tests that tests/README.md lists as scaled then do smaller work (a smaller mesh,
/// fewer directions): the same code runs under the sanitizer, and they check what holds at that
/// size; the figures of the full size are checked by the unsanitized suite, which runs them all.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif

/// Writes dir/small_scene.obj and .mtl, the embedded scenes' knot on a ground at a tenth of their
/// vertices (a (2, 3) knot of 32 x 6 standing 3.4 high, colour `knot_kd`, on a 12 x 12 ground of
/// 6 x 6 quads, grey 0.7; 241 vertices): the scaled tests' `--mesh` under a sanitizer. Returns
/// the OBJ's path.
std::string WriteSmallScene(const std::string& dir, const glm::vec3& knot_kd = glm::vec3(0.80f, 0.38f, 0.20f));

/// " --mesh PATH" of WriteSmallScene (in a scratch folder of `name`) under a sanitizer, "" without
/// one: the option that scales a test of the embedded or report scene down there.
std::string ScaledMesh(const std::string& name);

/// Scene options of a render that takes milliseconds: a tetrahedron (no normals) under the
/// furnace, closed-form transport.
std::string QuickScene();

/// `render` of QuickScene(), `frames` frames of `size`, into `out`: the arguments for RunPrt.
std::string QuickRender(const std::string& out, int frames, const std::string& size = "16x12");

/// Writes dir/scene.obj and dir/scene.mtl: a floor (side 2 at y = 0, 8 x 8 quads, first in the
/// file) of colour `floor_kd`, and beside it a wall (a box x in [-1.25, -1.05], 1.5 high) of
/// colour `wall_kd`. The floor sees only the wall, so its bounce light is the wall's colour. The
/// wall stands apart from the floor's edge: vertices shared by both would weld and average their
/// albedo. Returns the OBJ's path.
std::string WriteFloorAndWall(const std::string& dir, const glm::vec3& floor_kd, const glm::vec3& wall_kd);

/// Triangles of WriteFloorAndWall's floor and of its wall, in file order.
std::size_t FloorTriangles();
std::size_t WallTriangles();

/// Frame i of a run of `count` frames in `dir`, named as render names it (FrameName).
std::string FramePath(const std::string& dir, int i, int count);

/// The fields of one line of a CSV file prt writes: split at commas outside double quotes, the
/// quotes dropped ("a,\"b,c\"," gives a, b,c and an empty last field).
std::vector<std::string> CsvFields(const std::string& line);

/// Pixel (x, y) of an 8-bit image as integers.
glm::ivec3 PixelAt(const Image8& image, int x, int y);

/// Starts, in a child process, a render of 9999 frames of `size` (QuickScene, one thread,
/// stderr silenced) into `out`: a run that lasts long enough to be watched and killed.
/// `extra` options are appended. Returns the child's process id (the caller waits for it).
int StartLongRender(const std::string& out, const std::string& size, const std::vector<std::string>& extra = {});

/// Waits until the file `path` exists (polling every millisecond) or the child `pid` has exited,
/// then kills the child with SIGKILL and reaps it. Returns true if the file appeared while the
/// child ran. The wait is bounded (a minute) only so that a broken build cannot hang the suite;
/// it is not a time limit on prt.
bool KillWhenFileAppears(int pid, const std::string& path);

/// The same with the signal `sig` (SIGTERM, SIGINT: prt cleans up, then ends by the signal).
/// Returns the child's wait status, or -1 if it exited before the file appeared.
int SignalWhenFileAppears(int pid, const std::string& path, int sig);

/// Runs a shell command line, capturing its stdout and stderr.
RunResult RunCommand(const std::string& command);

/// Runs PrtBinary() with a shell-quoted argument string.
RunResult RunPrt(const std::string& arguments);

/// What `f` returns when run with `threads` worker threads; all cores again afterwards, also when
/// it throws (the determinism tests: same result for any thread count).
template <class F>
auto WithThreads(int threads, F&& f) {
  struct Restore {
    ~Restore() { SetThreadCount(0); }
  } restore;
  SetThreadCount(threads);
  return f();
}

}  // namespace prt::test
