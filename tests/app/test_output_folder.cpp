// Output folders never mix two runs (core/output_folder.h): a folder in use is refused at once,
// a lock left by a killed run blocks nothing, and after a successful run the folder holds
// exactly that run's outputs while files prt did not write stay untouched.
#include <doctest/doctest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <thread>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/atomic_file.h"
#include "core/output_folder.h"
#include "render/render_frames.h"
#include "tests/test_process.h"

namespace prt {
namespace {
namespace fs = std::filesystem;

using test::Q;


/// Names of the files in `dir`, hidden ones included.
std::set<std::string> Files(const std::string& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

/// The file's bytes, or "" while it does not exist yet (polling for another process's lock).
std::string ReadIfPresent(const std::string& path) {
  std::error_code ec;
  return fs::exists(path, ec) ? ReadFile(path) : std::string();
}

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("output folder: a folder in use is refused at once, a crashed run's lock blocks nothing") {
    const std::string dir = test::ScratchDir("folder_lock");
    // Hold the lock as a running prt would.
    const int fd = ::open((dir + "/" + OutputFolder::kLockName).c_str(), O_RDWR | O_CREAT, 0644);
    REQUIRE(fd >= 0);
    REQUIRE(::flock(fd, LOCK_EX | LOCK_NB) == 0);
    const auto refused = test::RunPrt(test::QuickRender(dir, 2));
    CHECK(refused.exit_code == kExitFolderBusy);  // try again: a CI wrapper retries
    CHECK(refused.err.find(dir + ": in use by another prt run") != std::string::npos);
    CHECK_FALSE(fs::exists(dir + "/frame_0000.png"));
    // The lock file stays where a killed run left it, but unheld: the next run goes ahead.
    ::close(fd);
    const auto after = test::RunPrt(test::QuickRender(dir, 2));
    CHECK(after.exit_code == 0);
    CHECK(fs::exists(dir + "/frame_0001.png"));
    CHECK_FALSE(fs::exists(dir + "/" + OutputFolder::kLockName));  // a finished run removes its lock
  }

  TEST_CASE("output folder: two renders into one folder at the same time, the second is refused") {
    const std::string dir = test::ScratchDir("folder_two_runs");
    const pid_t pid = test::StartLongRender(dir, "16x12");
    REQUIRE(pid > 0);
    // Wait until the first run holds the folder (its pid is in the lock file).
    const std::string lock = dir + "/" + OutputFolder::kLockName;
    bool holding = false;
    for (int tries = 0; tries < 20000 && !holding; ++tries) {
      holding = ReadIfPresent(lock) == std::to_string(pid);
      if (!holding) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    const auto second = test::RunPrt(test::QuickRender(dir, 3));
    ::kill(pid, SIGKILL);
    int status = 0;
    ::waitpid(pid, &status, 0);
    REQUIRE(holding);
    CHECK(second.exit_code == kExitFolderBusy);
    CHECK(second.err.find("in use by another prt run (process " + std::to_string(pid) + ")") != std::string::npos);
  }

  TEST_CASE("output folder: after a run the folder holds exactly its outputs, other files are untouched") {
    const std::string dir = test::ScratchDir("folder_exact");
    std::ofstream(dir + "/notes.txt") << "mine";
    std::ofstream(dir + "/frame_0007.png") << "a frame prt did not write";
    const auto first = test::RunPrt(test::QuickRender(dir, 5) + " --quiet");
    CHECK(first.exit_code == 0);
    CHECK(fs::exists(dir + "/frame_0004.png"));
    const auto second = test::RunPrt(test::QuickRender(dir, 3) + " --quiet");  // what CI runs: nothing printed
    CHECK(second.exit_code == 0);
    CHECK(second.err.empty());
    CHECK(Files(dir) == std::set<std::string>{".prt-outputs", "frame_0000.png", "frame_0001.png", "frame_0002.png",
                                              "frame_0007.png", "notes.txt", "transport.cache"});
    CHECK(ReadFile(dir + "/notes.txt") == "mine");
    CHECK(ReadFile(dir + "/frame_0007.png") == "a frame prt did not write");
    // Without --quiet the run says what it removed and what it left.
    const auto third = test::RunPrt(test::QuickRender(dir, 1));
    CHECK(third.err.find("outputs: removed 2 files an earlier run of this command wrote in " + dir +
                          " and this one did not (frame_0001.png ... frame_0002.png)") != std::string::npos);
    CHECK(third.err.find("note: 1 frame file in " + dir + " not written by this run was left untouched") !=
          std::string::npos);
  }

  TEST_CASE("output folder: a damaged list never makes a run remove a file outside the folder or in a sub-folder") {
    // The list names what this command wrote earlier; a run removes those it does not write
    // again. Entries edited by hand (or by a bad tool) to point elsewhere must be ignored.
    const std::string parent = test::ScratchDir("folder_damaged_list"), dir = parent + "/out";
    REQUIRE(test::RunPrt(test::QuickRender(dir, 1) + " --quiet").exit_code == 0);
    fs::create_directories(dir + "/sub");
    const std::string victims[] = {parent + "/outside.png", dir + "/sub/inner.png", parent + "/absolute.png"};
    for (const std::string& v : victims) std::ofstream(v) << "not prt's";
    std::ofstream(dir + "/" + OutputFolder::kListName, std::ios::app)
        << "render\t../outside.png\nrender\tsub/inner.png\nrender\t./sub/inner.png\nrender\t" << parent
        << "/absolute.png\nrender\t..\nrender\tsub\nrender\t.\n";
    const auto r = test::RunPrt(test::QuickRender(dir, 1) + " --quiet");
    CHECK(r.exit_code == 0);
    for (const std::string& v : victims) {
      CAPTURE(v);
      CHECK(fs::exists(v));
    }
    CHECK(fs::is_directory(dir + "/sub"));
    CHECK(fs::exists(dir + "/frame_0000.png"));
  }

  TEST_CASE("output folder: precompute leaves no transport file of an earlier mode") {
    const std::string dir = test::ScratchDir("folder_precompute");
    const std::string scene = "precompute --env furnace --samples 16 --mesh " + Q(test::Fixture("obj/quad.obj")) +
                              " --out " + Q(dir);
    const auto coloured = test::RunPrt(scene + " --transport interreflection --albedo 0.9,0.2,0.1");
    CHECK(coloured.exit_code == 0);
    CHECK(fs::exists(dir + "/transport_r.txt"));
    const auto shadowed = test::RunPrt(scene + " --transport shadowed");
    CHECK(shadowed.exit_code == 0);
    CHECK(Files(dir) == std::set<std::string>{".prt-outputs", "light.txt", "transport.txt", "transport.cache"});
  }

  TEST_CASE("output folder: rendering from sample files into their own folder keeps them, run after run") {
    const std::string dir = test::ScratchDir("folder_own_inputs");
    const auto samples = test::RunPrt("sample-files --quiet --out " + Q(dir));
    REQUIRE(samples.exit_code == 0);
    const std::string run = "render --mesh " + Q(dir + "/scene.obj") + " --env " + Q(dir + "/sky.hdr") +
                            " --samples 16 --frames 2 --size 32x24 --quiet --out " + Q(dir);
    for (int i = 0; i < 2; ++i) {
      CAPTURE(i);
      const auto r = test::RunPrt(run);
      CAPTURE(r.err);
      CHECK(r.exit_code == 0);
      for (const char* input : {"scene.obj", "scene.mtl", "sky.hdr"}) CHECK(std::filesystem::exists(dir + "/" + input));
    }
    const auto cube = test::RunPrt("light --env " + Q(dir + "/sky_cubemap"));
    CHECK(cube.exit_code == 0);
  }

  TEST_CASE("output folder: a failed run leaves the earlier outputs exactly, only its in-place files stay") {
    const std::string dir = test::ScratchDir("folder_failed");
    {
      OutputFolder folder(dir, {"test", {}});
      WriteFileAtomic(folder.Output("a.txt"), "a");
      WriteFileAtomic(folder.Output("b.txt"), "b");
      CHECK_FALSE(std::filesystem::exists(dir + "/a.txt"));  // staged until the run succeeds
      folder.Finish();
    }
    CHECK(Files(dir) == std::set<std::string>{".prt-outputs", "a.txt", "b.txt"});
    {
      OutputFolder failing(dir, {"test", {}});
      WriteFileAtomic(failing.Output("a.txt"), "a, failed run");
      WriteFileAtomic(failing.Output("c.txt"), "c");
      WriteFileAtomic(failing.OutputInPlace("cache"), "valid on its own");
      // no Finish(): the run failed
    }
    CHECK(Files(dir) == std::set<std::string>{".prt-outputs", "a.txt", "b.txt", "cache"});
    CHECK(ReadFile(dir + "/a.txt") == "a");
    {
      OutputFolder folder(dir, {"test", {}});
      WriteFileAtomic(folder.Output("a.txt"), "a2");
      CHECK(folder.Finish().removed == std::vector<std::string>{"b.txt", "cache"});
    }
    CHECK(Files(dir) == std::set<std::string>{".prt-outputs", "a.txt"});
    CHECK(ReadFile(dir + "/a.txt") == "a2");
  }

  TEST_CASE("output folder: a run never removes what it reads, even files an earlier run wrote there") {
    const std::string dir = test::ScratchDir("folder_inputs");
    {
      OutputFolder folder(dir, {"test", {}});
      WriteFileAtomic(folder.Output("scene.obj"), "v 0 0 0");
      WriteFileAtomic(folder.Output("scene.mtl"), "newmtl a");
      WriteFileAtomic(folder.Output("old.txt"), "x");
      folder.Finish();
    }
    {
      OutputFolder folder(dir, {"test", {}});
      folder.KeepInput(dir + "/scene.obj");
      folder.KeepInput(dir + "/./scene.mtl");  // paths are compared normalised
      WriteFileAtomic(folder.Output("frame.png"), "f");
      CHECK(folder.Finish().removed == std::vector<std::string>{"old.txt"});
    }
    CHECK(Files(dir) == std::set<std::string>{".prt-outputs", "frame.png", "scene.mtl", "scene.obj"});
    // No longer listed as prt's: a later run that does not read them leaves them alone too.
    {
      OutputFolder folder(dir, {"test", {}});
      WriteFileAtomic(folder.Output("frame.png"), "g");
      CHECK(folder.Finish().removed.empty());
    }
    CHECK(Files(dir).count("scene.obj") == 1);
  }

  TEST_CASE("output folder: a run that reads a folder inside the output folder keeps all of it") {
    const std::string dir = test::ScratchDir("folder_input_folder");
    {
      OutputFolder folder(dir, {"test", {}});
      WriteFileAtomic(folder.Output("sky.hdr"), "h");
      WriteFileAtomic(folder.Output("skyline.txt"), "not under sky.hdr");
      folder.Finish();
    }
    OutputFolder folder(dir, {"test", {}});
    folder.KeepInput(dir + "/sky.hdr");
    CHECK(folder.Finish().removed == std::vector<std::string>{"skyline.txt"});  // a shared prefix is not a folder
  }

  TEST_CASE("output folder: frame names keep frame order past 9999 frames") {
    CHECK(FrameName(0, 120) == "frame_0000.png");
    CHECK(FrameName(9999, 10000) == "frame_9999.png");
    CHECK(FrameName(0, 10001) == "frame_00000.png");
    CHECK(FrameName(10000, 10001) == "frame_10000.png");
    CHECK(FrameName(5, 100000) == "frame_00005.png");
    CHECK(FrameName(99999, 100000) == "frame_99999.png");
    // Lexical order is frame order for every count.
    for (int count : {10, 10001, 100001})
      CHECK(FrameName(count / 2 - 1, count) < FrameName(count / 2, count));
    CHECK(FrameName(999, 10001) < FrameName(10000, 10001));
  }
}

}  // namespace prt
