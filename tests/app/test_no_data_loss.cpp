// No data lost: outputs are written to a temporary name in the same folder and renamed when
// complete (core/atomic_file.h), so a run killed with SIGKILL in the middle of its frames leaves
// every frame either the old complete file or a new complete one, never a truncated file.
//
// What SIGKILL can leave: the one temporary file being written at the kill (named
// `.frame_NNNN.png.prt-tmp<pid>_<n>`: a dot file, ignored by every reader, never counted as a
// frame), and the folder's lock file, which is held by no process once the run is dead. A later
// successful run into the folder removes the temporary file (its writer's pid, in its name, is
// gone) and reuses the lock (core/output_folder.h).
#include <doctest/doctest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

#include "core/atomic_file.h"
#include "core/output_folder.h"
#include "core/error.h"
#include "io/png_io.h"
#include "tests/test_process.h"

namespace prt {
namespace {
namespace fs = std::filesystem;
using test::Q;

/// A complete 8x8 PNG of one grey level: the "earlier output" a new run may replace.
std::string MarkerPng(unsigned char level) {
  Image8 image;
  image.width = image.height = 8;
  image.rgb.assign(3 * 8 * 8, level);
  return EncodePng(image);
}

bool IsTemp(const std::string& name) { return AtomicFile::IsTemporaryName(name); }

/// Writes frame_0000.png .. frame_{n-1}.png as markers; returns their bytes by name. `by_prt`:
/// as an earlier prt render would (listed as its outputs), else as someone else's files.
std::map<std::string, std::string> FillWithMarkers(const std::string& dir, int n, bool by_prt) {
  std::map<std::string, std::string> old;
  std::optional<OutputFolder> folder;
  if (by_prt) folder.emplace(dir, OutputPlan{"render", {}});
  for (int i = 0; i < n; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", i);
    old[name] = MarkerPng(static_cast<unsigned char>(i % 200));
    WriteFileAtomic(folder ? folder->Output(name) : dir + "/" + name, old[name]);
  }
  if (folder) folder->Finish();
  return old;
}

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("no data lost: a render killed mid-run leaves every earlier frame as it was") {
    const std::string dir = test::ScratchDir("no_data_loss_kill");
    constexpr int kMarkers = 400;
    const auto old = FillWithMarkers(dir, kMarkers, true);

    // Many small frames (four-digit names, like the markers): the run would take a while; it is
    // killed once 20 frames are written (into the staging folder, until the run succeeds).
    const pid_t pid = test::StartLongRender(dir, "48x32");
    REQUIRE(pid > 0);
    const std::string staging = dir + "/" + OutputFolder::kStagingName;
    // Killed once frame 20 is staged; the kill ends it (not an exit of its own).
    REQUIRE(test::KillWhenFileAppears(pid, staging + "/frame_0020.png"));

    // The folder itself: every earlier frame intact, nothing new but prt's own files.
    int kept = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
      const std::string name = entry.path().filename().string();
      if (name == "transport.cache" || name.rfind(".prt-", 0) == 0) continue;  // the cache; lock, staging, list
      CAPTURE(name);
      REQUIRE(old.count(name) == 1);
      CHECK(ReadFile(entry.path().string()) == old.at(name));
      ++kept;
    }
    CHECK(kept == kMarkers);
    // What the killed run staged is complete frames, and at most the one being written.
    int staged = 0, temps = 0;
    for (const auto& entry : fs::directory_iterator(staging)) {
      const std::string name = entry.path().filename().string();
      if (IsTemp(name)) {
        ++temps;
        continue;
      }
      CAPTURE(name);
      Image8 image;
      CHECK_NOTHROW(image = ReadPng(entry.path().string()));  // complete, never truncated
      CHECK(image.width == 48);
      ++staged;
    }
    MESSAGE("after SIGKILL: " << kept << " earlier frames intact, " << staged << " frames and " << temps
                              << " temporary file(s) in the killed run's staging folder");
    CHECK(staged >= 21);
    CHECK(temps <= 1);

    // The killed run's lock blocks nothing, and the next successful run removes its staging folder.
    const auto later = test::RunPrt("render " + test::QuickScene() + " --frames 1 --size 8x8 --quiet --out " + Q(dir));
    CHECK(later.exit_code == 0);
    CHECK_FALSE(fs::exists(staging));
    for (const auto& entry : fs::directory_iterator(dir)) CHECK_FALSE(IsTemp(entry.path().filename().string()));
    // The markers stand for an earlier render's frames: this render of one frame removes the rest.
    CHECK_FALSE(fs::exists(dir + "/frame_0001.png"));
  }

  TEST_CASE("no data lost: frames prt did not write are never removed, failed runs keep old outputs") {
    const std::string dir = test::ScratchDir("no_data_loss_fewer");
    const auto old = FillWithMarkers(dir, 10, false);
    // Not frame names: prt's frames are frame_N.png in lower case (FrameName), so these are not
    // counted among the frames it left untouched.
    WriteFileAtomic(dir + "/FRAME_0011.PNG", "x");
    WriteFileAtomic(dir + "/frame_0012.png.txt", "x");
    const std::string run = "render --env furnace --transport unshadowed --frames 3 --size 16x16 --mesh " +
                            Q(test::Fixture("obj/quad.obj")) + " --out " + Q(dir);
    // Frames 0..2 would replace files prt did not write: refused before any work, naming one.
    const auto refused = test::RunPrt(run);
    CHECK(refused.exit_code == 1);
    CHECK(refused.err.find(dir + "/frame_0000.png: exists and prt did not write it") != std::string::npos);
    CHECK_FALSE(fs::exists(dir + "/transport.cache"));  // no precompute happened
    for (const auto& [name, bytes] : old) CHECK(ReadFile(dir + "/" + name) == bytes);
    // --replace replaces them, keeping each as NAME.orig.
    const auto r = test::RunPrt(run + " --replace");
    CAPTURE(r.err);
    CHECK(r.exit_code == 0);
    // The markers were not written by prt: frames 3..9 are left, and the run says so.
    CHECK(r.err.find("note: 7 frame files in " + dir + " not written by this run were left untouched") !=
          std::string::npos);
    CHECK(r.err.find("outputs: replaced 3 files prt did not write in " + dir +
                     " (--replace), kept as frame_0000.png.orig ... frame_0002.png.orig") != std::string::npos);
    for (const auto& [name, bytes] : old) {
      CAPTURE(name);
      REQUIRE(fs::exists(dir + "/" + name));
      if (name >= "frame_0003.png") {
        CHECK(ReadFile(dir + "/" + name) == bytes);  // untouched
      } else {
        CHECK(ReadFile(dir + "/" + name) != bytes);  // replaced, and kept
        CHECK(ReadFile(dir + "/" + name + ".orig") == bytes);
      }
    }

    // A run that fails (bad mesh) leaves the earlier frames, cache and text files as they were.
    std::ofstream(dir + "/light.txt") << "earlier light\n";
    const std::string cache_before = ReadFile(dir + "/transport.cache");
    const auto failed =
        test::RunPrt("render --env furnace --frames 2 --mesh " + Q(test::Fixture("obj/no_faces.obj")) + " --out " + Q(dir));
    CHECK(failed.exit_code == 1);
    const auto failed_pre =
        test::RunPrt("precompute --env " + Q(test::Fixture("images/truncated.png")) + " --out " + Q(dir));
    CHECK(failed_pre.exit_code == 1);
    CHECK(ReadFile(dir + "/light.txt") == "earlier light\n");
    CHECK(ReadFile(dir + "/transport.cache") == cache_before);
    for (const auto& [name, bytes] : old)
      if (name >= "frame_0003.png") CHECK(ReadFile(dir + "/" + name) == bytes);
    for (const auto& entry : fs::directory_iterator(dir)) CHECK_FALSE(IsTemp(entry.path().filename().string()));
  }
}

}  // namespace prt
