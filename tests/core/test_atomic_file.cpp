#include <doctest/doctest.h>

#include <filesystem>

#include "core/atomic_file.h"
#include "core/error.h"
#include "tests/test_support.h"

namespace fs = std::filesystem;

TEST_SUITE("core") {
  TEST_CASE("WriteFileAtomic replaces a file completely and leaves no temporary behind") {
    const std::string dir = prt::test::ScratchDir("atomic");
    const std::string path = dir + "/a.txt";
    prt::WriteFileAtomic(path, "old");
    prt::WriteFileAtomic(path, "new content");
    CHECK(prt::ReadFile(path) == "new content");
    int entries = 0;
    for (auto& e : fs::directory_iterator(dir)) (void)e, ++entries;
    CHECK(entries == 1);
  }

  TEST_CASE("An uncommitted AtomicFile leaves the old file intact") {
    const std::string dir = prt::test::ScratchDir("atomic2");
    const std::string path = dir + "/a.txt";
    prt::WriteFileAtomic(path, "keep me");
    {
      prt::AtomicFile f(path);
      prt::WriteFileAtomic(f.temp_path(), "half");  // written but never committed
    }
    CHECK(prt::ReadFile(path) == "keep me");
  }

  TEST_CASE("ReadFile names the path for a missing file and a directory") {
    CHECK_THROWS_WITH_AS(prt::ReadFile("/nonexistent/x.obj"), "/nonexistent/x.obj: no such file",
                         prt::Error);
    const std::string dir = prt::test::ScratchDir("atomic3");
    CHECK_THROWS_AS(prt::ReadFile(dir), prt::Error);
  }
}
