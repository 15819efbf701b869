// prt render --frame-range and prt video as a farm's frame tasks run them, as processes: ranges
// written at once into one folder are the full run's frames byte for byte (a range after frame 0
// takes frame 0's exposure), `auto` takes the range from the scheduler, refusals come before any
// work, and prt video of the ranges' frames is the one-run video.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "core/output_folder.h"
#include "tests/test_process.h"

namespace prt {
namespace {

namespace fs = std::filesystem;
using test::Q;

/// Every name in `dir`, hidden files and folders too.
std::set<std::string> Names(const std::string& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

/// The frame files in `dir`.
std::set<std::string> Frames(const std::string& dir) {
  std::set<std::string> names;
  for (const std::string& n : Names(dir))
    if (n.rfind("frame_", 0) == 0) names.insert(n);
  return names;
}

// Auto exposure measured on frame 0, an orbiting camera and a turning light: every frame differs,
// and a range that does not start at 0 must still take frame 0's exposure, seen from frame 0's
// camera (half a turn of orbit: frame 3's view measures another EV, -1.8 against -1.7).
const std::string kScene = " --samples 64 --hidden-samples 16 --frames 7 --size 40x30 --orbit 180";

}  // namespace

TEST_SUITE("farm") {
TEST_CASE("frame ranges: ranges written at once into one folder are the full run's frames and list, byte for byte") {
  const std::string scene = test::SmallSceneOption("ranges_scene") + kScene;
  const std::string one = test::ScratchDir("ranges_one"), parts = test::ScratchDir("ranges_parts");
  REQUIRE(test::RunPrt("render" + scene + " --out " + Q(one) + " --quiet").exit_code == 0);
  // The transport first (a cache every range then reads), as a farm's merge writes it: frame 0
  // alone.
  REQUIRE(test::RunPrt("render" + scene + " --out " + Q(parts) + " --frame-range 0-0 --quiet").exit_code == 0);
  CHECK(Frames(parts) == std::set<std::string>{"frame_0000.png"});
  // Three ranges at once, as three tasks of an array.
  const std::string prt = Q(test::PrtBinary()) + " render" + scene + " --out " + Q(parts);
  const test::RunResult r = test::RunCommand("(" + prt + " --frame-range 0-2 & " + prt + " --frame-range 3-3 2>" +
                                             Q(parts + ".err") + " & " + prt + " --frame-range 4-6 & wait) >/dev/null 2>&1");
  REQUIRE(r.exit_code == 0);
  CHECK(test::FolderFiles(parts) == test::FolderFiles(one));
  CHECK(Names(parts) == Names(one));  // no lock file or staging folder left
  std::ifstream in(parts + ".err");
  const std::string err((std::istreambuf_iterator<char>(in)), {});
  CHECK(err.find("frames: 3 to 3 of 7 (--frame-range 3-3)") != std::string::npos);
  CHECK(err.find("frame 0's mesh pixels (drawn, not written") != std::string::npos);

  // A range run again over its own frames: nothing of the others' is removed, and the others'
  // frames are not "frames prt has no record of".
  const test::RunResult again = test::RunPrt("render" + scene + " --out " + Q(parts) + " --frame-range 4-6");
  REQUIRE(again.exit_code == 0);
  CHECK(again.err.find("not written by this run") == std::string::npos);
  CHECK(test::FolderFiles(parts) == test::FolderFiles(one));
}

TEST_CASE("frame ranges: a file prt did not write under one of the range's names is refused before any work") {
  const std::string dir = test::ScratchDir("ranges_foreign");
  std::ofstream(dir + "/frame_0004.png") << "the user's";  // the range's last frame
  const test::RunResult r = test::RunPrt("render" + test::SmallSceneOption("ranges_foreign_scene") + kScene +
                                         " --out " + Q(dir) + " --frame-range 2-4");
  CHECK(r.exit_code == 1);
  CHECK(r.err.find(dir + "/frame_0004.png: exists and prt did not write it") != std::string::npos);
  // Before any work: no transport computed, no frame written.
  CHECK(Names(dir) == std::set<std::string>{"frame_0004.png"});
}

TEST_CASE("frame ranges: auto takes block I of N of the frames from the scheduler, every frame once") {
  const std::string dir = test::ScratchDir("ranges_auto");
  std::set<std::string> seen;
  std::size_t total = 0;
  for (int i = 0; i < 3; ++i) {
    const std::string out = dir + "/task" + std::to_string(i);
    const test::RunResult r = test::RunCommand("SLURM_ARRAY_TASK_ID=" + std::to_string(i) +
                                               " SLURM_ARRAY_TASK_COUNT=3 " + Q(test::PrtBinary()) + " " +
                                               test::QuickRender(out, 7) + " --frame-range auto");
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    CHECK(r.err.find("(block " + std::to_string(i) + " of 3: SLURM_ARRAY_TASK_ID=" + std::to_string(i)) !=
          std::string::npos);
    const std::set<std::string> frames = Frames(out);
    CHECK(frames.size() >= 2);  // 7 frames in 3 blocks: 2 or 3 each
    total += frames.size();
    seen.insert(frames.begin(), frames.end());
  }
  CHECK(total == 7);
  CHECK(seen.size() == 7);
  // The blocks are consecutive: task 0 starts at frame 0, task 2 ends at frame 6.
  CHECK(Frames(dir + "/task0").count("frame_0000.png") == 1);
  CHECK(Frames(dir + "/task2").count("frame_0006.png") == 1);
}

TEST_CASE("frame ranges: a range that cannot be, and what a range cannot write, refused before any work") {
  const std::string dir = test::ScratchDir("ranges_refused");
  struct Case {
    const char* options;
    const char* says;
  };
  const Case cases[] = {
      {" --frame-range 3-2", "is not a range"},
      {" --frame-range 5-7", "goes past the last frame, 6"},
      {" --frame-range -1-2", "is not a range"},
      {" --frame-range 2", "is not a range"},
      {" --frame-range 1.5-3", "is not a range"},
      {" --frame-range 0-1 --video turn.png", "--video: not with --frame-range"},
      {" --frame-range 1-2 --vertex-radiance radiance.txt", "not with a --frame-range that starts at frame 1"},
      {" --frame-range auto", "--shard auto"},  // no scheduler in this environment
  };
  for (const Case& c : cases) {
    CAPTURE(c.options);
    const std::string out = dir + "/out";
    const test::RunResult r =
        test::RunCommand("env -u SLURM_ARRAY_TASK_ID -u JOB_COMPLETION_INDEX " + Q(test::PrtBinary()) + " " +
                         test::QuickRender(out, 7) + c.options);
    CHECK(r.exit_code == 2);
    CHECK_MESSAGE(r.err.find(c.says) != std::string::npos, r.err);
    CHECK_FALSE(fs::exists(out));
  }
  const test::RunResult many = test::RunCommand("SLURM_ARRAY_TASK_ID=0 SLURM_ARRAY_TASK_COUNT=8 " +
                                                Q(test::PrtBinary()) + " " + test::QuickRender(dir + "/many", 7) +
                                                " --frame-range auto");
  CHECK(many.exit_code == 2);
  CHECK(many.err.find("8 tasks for 7 frames") != std::string::npos);
}

TEST_CASE("prt video: the frames of ranges give the one-run video byte for byte; a missing or odd frame is refused") {
  const std::string scene = test::SmallSceneOption("video_scene") + kScene;
  const std::string one = test::ScratchDir("video_one"), parts = test::ScratchDir("video_parts");
  REQUIRE(test::RunPrt("render" + scene + " --out " + Q(one) + " --video " + Q(one + "/turn.png") + " --fps 12 --quiet")
              .exit_code == 0);
  for (const char* range : {"0-3", "4-6"})
    REQUIRE(test::RunPrt("render" + scene + " --out " + Q(parts) + " --frame-range " + range + " --quiet").exit_code == 0);
  const test::RunResult v = test::RunPrt("video " + Q(parts) + " --video " + Q(parts + "/turn.png") + " --fps 12");
  REQUIRE_MESSAGE(v.exit_code == 0, v.err);
  CHECK(v.err.find("7 frames of 40x30 at 12 fps") != std::string::npos);
  CHECK(test::FolderFiles(parts) == test::FolderFiles(one));  // the video listed under render, as one run lists it
  // Outside the folder too.
  const std::string outside = test::ScratchDir("video_outside") + "/turn.apng";
  REQUIRE(test::RunPrt("video " + Q(parts) + " --video " + Q(outside) + " --fps 12 --quiet").exit_code == 0);
  CHECK(test::FolderFiles(fs::path(outside).parent_path().string()).at("turn.apng") ==
        test::FolderFiles(one).at("turn.png"));

  // A frame missing: refused with its name, no video written.
  const std::string gap = test::ScratchDir("video_gap");
  for (const char* range : {"0-2", "4-6"})
    REQUIRE(test::RunPrt("render" + scene + " --out " + Q(gap) + " --frame-range " + range + " --quiet").exit_code == 0);
  test::RunResult r = test::RunPrt("video " + Q(gap) + " --video " + Q(gap + "/turn.png"));
  CHECK(r.exit_code == 1);
  CHECK(r.err.find(gap + "/frame_0003.png: missing") != std::string::npos);
  CHECK_FALSE(fs::exists(gap + "/turn.png"));
  // --frames longer than the frames there: the first missing one named.
  r = test::RunPrt("video " + Q(parts) + " --video " + Q(parts + "/long.png") + " --frames 9");
  CHECK(r.exit_code == 1);
  CHECK(r.err.find(parts + "/frame_0007.png: missing (2 of the 9") != std::string::npos);
  CHECK_FALSE(fs::exists(parts + "/long.png"));
  // A frame of another size.
  const std::string odd = test::ScratchDir("video_odd");
  REQUIRE(test::RunPrt(test::QuickRender(odd, 3, "16x12")).exit_code == 0);
  REQUIRE(test::RunPrt(test::QuickRender(odd, 3, "18x12") + " --frame-range 2-2").exit_code == 0);
  r = test::RunPrt("video " + Q(odd) + " --video " + Q(odd + "/turn.png"));
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("frame_0002.png: 18x12, not frame 0's 16x12") != std::string::npos);
  CHECK_FALSE(fs::exists(odd + "/turn.png"));
  // No --video, or no folder.
  CHECK(test::RunPrt("video " + Q(parts)).exit_code == 2);
  CHECK(test::RunPrt("video " + Q(parts + "/none") + " --video x.png").exit_code == 1);
}

TEST_CASE("prt video: an .mp4 from the ranges' frames is the one run's, byte for byte" * test::NeedsFfmpeg()) {
  const std::string scene = test::SmallSceneOption("video_mp4_scene") + kScene;
  const std::string one = test::ScratchDir("video_mp4_one"), parts = test::ScratchDir("video_mp4_parts");
  REQUIRE(test::RunPrt("render" + scene + " --out " + Q(one) + " --video " + Q(one + "/turn.mp4") + " --quiet")
              .exit_code == 0);
  for (const char* range : {"0-4", "5-6"})
    REQUIRE(test::RunPrt("render" + scene + " --out " + Q(parts) + " --frame-range " + range + " --quiet").exit_code == 0);
  REQUIRE(test::RunPrt("video " + Q(parts) + " --video " + Q(parts + "/turn.mp4") + " --quiet").exit_code == 0);
  CHECK(test::FolderFiles(parts) == test::FolderFiles(one));
}
}  // TEST_SUITE

}  // namespace prt
