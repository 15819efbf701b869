#pragma once
/// \file
/// Helpers shared by the tests of every tier: where the shared course data is, scratch folders,
/// small scenes. Nothing here starts a process: that is tests/test_process.h, which only the
/// programs of the e2e and readme tiers link (tests/README.md, "Tiers").

#include <doctest/doctest.h>

#include <functional>
#include <optional>
#include <map>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/parallel.h"

namespace prt {
struct Image8;  // core/image.h
}

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

/// Every file of the folder `dir` (hidden ones too, not its subfolders'), by name, with its bytes:
/// to compare two output folders byte for byte.
std::map<std::string, std::string> FolderFiles(const std::string& dir);

/// True when this machine can run the slurm tier's one-node Slurm (tests/farm/slurm_cluster.h):
/// root, and slurmctld, slurmd, munged, sbatch and sinfo on PATH (Debian's slurm-wlm and munge).
bool SlurmAvailable();
/// The decorator of a test case that needs SlurmAvailable(): skipped, and counted as skipped by
/// the runner, where it is false (PRT_REQUIRE_SLURM=1: the run fails instead).
doctest::skip NeedsSlurm();
/// The message of the prt::Error (core/error.h) that `run` throws; "" when it throws none.
std::string ErrorMessage(const std::function<void()>& run);

/// An empty scratch folder for one test, under the build folder's test-tmp/ (or the folder
/// $PRT_TEST_TMP names: the sanitizer passes run the e2e program of the Release build with their
/// own).
std::string ScratchDir(const std::string& name);

/// `text` as one single-quoted shell word (a quote inside it included).
std::string ShellQuote(const std::string& text);

/// ShellQuote under a short name, for the paths in command lines: "render --out " + Q(dir).
inline std::string Q(const std::string& text) { return ShellQuote(text); }

/// Whether this test program is built under a sanitizer (scripts/sanitize.sh: ASan + UBSan, or
/// TSan). The in-process tests that tests/README.md lists as scaled then do smaller work (a
/// smaller mesh, fewer directions): the same code runs under the sanitizer, and they check what
/// holds at that size; the figures of the full size are checked by the unsanitized suite.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif

/// Writes dir/small_scene.obj and .mtl, the embedded scenes' knot on a ground at a tenth of their
/// vertices (a (2, 3) knot of 32 x 6 standing 3.4 high, colour `knot_kd`, on a 12 x 12 ground of
/// 6 x 6 quads, grey 0.7; 241 vertices): the `--mesh` of the tests that need a scene with shadows
/// and bounces in seconds. Returns the OBJ's path.
std::string WriteSmallScene(const std::string& dir, const glm::vec3& knot_kd = glm::vec3(0.80f, 0.38f, 0.20f));

/// " --mesh PATH" of WriteSmallScene in a scratch folder of `name`: the option that puts a test's
/// run on the small scene.
std::string SmallSceneOption(const std::string& name);

/// Scene options of a render that takes milliseconds: a tetrahedron (no normals) under the
/// furnace, closed-form transport.
std::string QuickScene();

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

/// The pool's thread count set for a scope (code that runs ParallelFor inside it, on threads of
/// its own as well), all cores again after it, also when it is left by an exception.
class ThreadCountScope {
 public:
  explicit ThreadCountScope(int threads) { SetThreadCount(threads); }
  ~ThreadCountScope() { SetThreadCount(0); }
  ThreadCountScope(const ThreadCountScope&) = delete;
  ThreadCountScope& operator=(const ThreadCountScope&) = delete;
};

/// What `f` returns when run with `threads` worker threads; all cores again afterwards, also when
/// it throws (the determinism tests: same result for any thread count).
template <class F>
auto WithThreads(int threads, F&& f) {
  const ThreadCountScope scope(threads);
  return f();
}

}  // namespace prt::test
