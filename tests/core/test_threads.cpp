// The threads tier of src/core besides the pool (test_parallel.cpp): what the stages' threads
// share. A progress bar advanced from every thread while another reads it; atomic files made
// from several threads at once, each with a temporary name of its own; an output folder naming
// its outputs from the frame writer's threads; the signal cleanup's registry, which every file
// and child joins and leaves from whatever thread makes it. Checked for what a race would break
// (counts, names, contents), and watched by ThreadSanitizer.
#include <doctest/doctest.h>

#include <atomic>
#include <filesystem>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "core/atomic_file.h"
#include "core/output_folder.h"
#include "core/progress.h"
#include "core/signal_cleanup.h"
#include "tests/threads_util.h"

namespace prt {
namespace {

namespace fs = std::filesystem;

constexpr int kThreads = test::kManyThreads;


}  // namespace

TEST_SUITE("core") {
  TEST_CASE("threads: a progress bar advanced from every thread counts every item, read meanwhile from another") {
    constexpr std::size_t kPerThread = 5000;
    std::atomic<bool> done{false};
    double last_seen = 0.0;
    bool went_back = false;
    std::thread reader([&] {
      while (!done) {
        const ProgressReading r = LatestProgress();
        if (r.active && r.fraction < last_seen) went_back = true;
        if (r.active) last_seen = r.fraction;
      }
    });
    {
      Progress bar("counting", kThreads * kPerThread);
      test::OnThreads(kThreads, [&](int) {
        for (std::size_t i = 0; i < kPerThread; ++i) bar.Advance(1);
      });
      const ProgressReading whole = LatestProgress();
      CHECK(whole.active);
      CHECK(whole.fraction == 1.0);
      CHECK(whole.label == "counting");
    }
    done = true;
    reader.join();
    CHECK_FALSE(went_back);
    CHECK_FALSE(LatestProgress().active);
  }

  TEST_CASE("threads: atomic files made at once on several threads each take a temporary name of their own") {
    const std::string dir = test::ScratchDir("threads_atomic_files");
    constexpr int kPerThread = 25;
    std::vector<std::set<std::string>> temps(kThreads);
    test::OnThreads(kThreads, [&](int t) {
      for (int i = 0; i < kPerThread; ++i) {
        // All threads write the same destination in turn, and files of their own.
        AtomicFile shared(dir + "/shared.txt");
        temps[std::size_t(t)].insert(shared.temp_path());
        WriteFileAtomic(dir + "/" + std::to_string(t) + "_" + std::to_string(i) + ".txt", std::string(100 + i, char('a' + t)));
      }
    });
    std::set<std::string> all;
    for (const auto& s : temps) all.insert(s.begin(), s.end());
    CHECK(all.size() == std::size_t(kThreads * kPerThread));  // no two AtomicFiles shared a temporary name
    for (int t = 0; t < kThreads; ++t)
      for (int i = 0; i < kPerThread; ++i)
        CHECK(ReadFile(dir + "/" + std::to_string(t) + "_" + std::to_string(i) + ".txt") == std::string(100 + i, char('a' + t)));
    for (const auto& entry : fs::directory_iterator(dir)) CHECK_FALSE(AtomicFile::IsTemporaryName(entry.path().filename().string()));
  }

  TEST_CASE("threads: an output folder names its outputs from several threads, and Finish moves every one into place") {
    const std::string dir = test::ScratchDir("threads_output_folder") + "/out";
    constexpr int kPerThread = 20;
    {
      OutputFolder folder(dir, OutputPlan{"render", {}});
      test::OnThreads(kThreads, [&](int t) {
        for (int i = 0; i < kPerThread; ++i) {
          const std::string name = "f" + std::to_string(t) + "_" + std::to_string(i) + ".txt";
          WriteFileAtomic(folder.Output(name), name);
          CHECK_FALSE(folder.IsForeign(name));
        }
      });
      folder.Finish();
    }
    for (int t = 0; t < kThreads; ++t)
      for (int i = 0; i < kPerThread; ++i) {
        const std::string name = "f" + std::to_string(t) + "_" + std::to_string(i) + ".txt";
        CHECK(ReadFile(dir + "/" + name) == name);
      }
  }

  TEST_CASE("threads: the signal cleanup's registry takes and gives back entries from every thread at once") {
    // Without InstallSignalCleanup (the tests' own process) the registry is kept and never used:
    // what is checked is that joining and leaving it from many threads is safe.
    const std::string dir = test::ScratchDir("threads_cleanup");
    test::OnThreads(kThreads, [&](int t) {
      for (int i = 0; i < 200; ++i) {
        CleanupOnSignal file(dir + "/" + std::to_string(t) + "_" + std::to_string(i), CleanupKind::kFile);
        CleanupOnSignal moved = std::move(file);
        if (i % 2) moved.Release();
      }
    });
    CHECK(fs::is_empty(dir));
  }
}

}  // namespace prt
