// Atomic outputs: a file is complete or untouched, never half-written. The failure cases are made
// deterministic: the write is cut short by a file-size limit (RLIMIT_FSIZE, SIGXFSZ ignored, so
// write() fails with EFBIG part way through), and the old bytes must still be there.
#include <doctest/doctest.h>

#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <sys/resource.h>

#include "core/atomic_file.h"
#include "core/error.h"
#include "tests/test_support.h"

namespace fs = std::filesystem;

namespace {

/// The names in `dir`.
std::vector<std::string> Entries(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  return names;
}

/// Bytes that differ from position to position, so a partial overwrite cannot go unnoticed.
std::string Pattern(std::size_t size, char seed) {
  std::string s(size, '\0');
  for (std::size_t i = 0; i < size; ++i) s[i] = static_cast<char>(seed + i * 7 % 61);
  return s;
}

/// While alive, this process may write files of at most `bytes` bytes; a longer write fails
/// with EFBIG instead of raising SIGXFSZ.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    ::getrlimit(RLIMIT_FSIZE, &saved_);
    old_handler_ = std::signal(SIGXFSZ, SIG_IGN);
    rlimit limited = saved_;
    limited.rlim_cur = bytes;
    REQUIRE(::setrlimit(RLIMIT_FSIZE, &limited) == 0);
  }
  ~FileSizeLimit() {
    ::setrlimit(RLIMIT_FSIZE, &saved_);
    std::signal(SIGXFSZ, old_handler_);
  }

 private:
  rlimit saved_{};
  void (*old_handler_)(int) = nullptr;
};

}  // namespace

TEST_SUITE("core") {
  TEST_CASE("WriteFileAtomic replaces a longer file completely and leaves no temporary behind") {
    const std::string dir = prt::test::ScratchDir("atomic");
    const std::string path = dir + "/a.txt";
    prt::WriteFileAtomic(path, Pattern(5000, 'a'));
    prt::WriteFileAtomic(path, "new content");
    CHECK(prt::ReadFile(path) == "new content");
    CHECK(Entries(dir) == std::vector<std::string>{"a.txt"});
  }

  TEST_CASE("a write cut short part way leaves the old file's bytes exactly, and no temporary") {
    const std::string dir = prt::test::ScratchDir("atomic_cut");
    const std::string path = dir + "/frame.png";
    const std::string old = Pattern(3000, 'o');
    prt::WriteFileAtomic(path, old);
    {
      // 4 KiB allowed, 64 KiB asked: the first 4 KiB are written, then write() fails.
      const FileSizeLimit limit(4096);
      CHECK_THROWS_WITH_AS(prt::WriteFileAtomic(path, Pattern(65536, 'n')), doctest::Contains(path.c_str()), prt::Error);
    }
    CHECK(prt::ReadFile(path) == old);
    CHECK(Entries(dir) == std::vector<std::string>{"frame.png"});
  }

  TEST_CASE("an AtomicFile writes beside its destination, which keeps its old bytes until Commit") {
    const std::string dir = prt::test::ScratchDir("atomic2");
    const std::string path = dir + "/a.txt";
    prt::WriteFileAtomic(path, "keep me");
    {
      prt::AtomicFile f(path);
      CHECK(fs::path(f.temp_path()).parent_path() == fs::path(path).parent_path());  // same file system
      std::ofstream(f.temp_path(), std::ios::binary) << "half";
      CHECK(prt::ReadFile(path) == "keep me");
      // destroyed without Commit: the temporary goes, the old file stays
    }
    CHECK(prt::ReadFile(path) == "keep me");
    CHECK(Entries(dir) == std::vector<std::string>{"a.txt"});
    {
      prt::AtomicFile f(path);
      std::ofstream(f.temp_path(), std::ios::binary) << "whole";
      CHECK(prt::ReadFile(path) == "keep me");
      f.Commit();
    }
    CHECK(prt::ReadFile(path) == "whole");
    CHECK(Entries(dir) == std::vector<std::string>{"a.txt"});
  }

  TEST_CASE("ReadFile names the path for a missing file and a directory") {
    CHECK_THROWS_WITH_AS(prt::ReadFile("/nonexistent/x.obj"), "/nonexistent/x.obj: no such file",
                         prt::Error);
    const std::string dir = prt::test::ScratchDir("atomic3");
    CHECK_THROWS_AS(prt::ReadFile(dir), prt::Error);
  }

  TEST_CASE("IsTemporaryName: the names AtomicFile gives, with their process, and no other") {
    const prt::AtomicFile file(prt::test::ScratchDir("atomic_names") + "/frame_0001.png");
    const std::string name = file.temp_path().substr(file.temp_path().rfind('/') + 1);
    long pid = 0;
    CHECK(prt::AtomicFile::IsTemporaryName(name, &pid));
    CHECK(pid == long(::getpid()));
    CHECK(prt::AtomicFile::IsTemporaryName(".a.png.prt-tmp123456789_0", &pid));
    CHECK(pid == 123456789);
    for (const char* other : {"a.png.prt-tmp12_3",           // not hidden
                              ".a.png.prt-tmp_3",            // no pid
                              ".a.png.prt-tmp1234567890_3",  // a pid of ten digits
                              ".a.png.prt-tmp12_",           // no count
                              ".a.png.prt-tmp12_3x", ".a.png.prt-tmp1x_3", ".a.png.prt-tmp12", ".a.png", ".prt-tmp12_3",
                              "..prt-tmp12_3"}) {  // the last two: no file name before the tag
      CAPTURE(other);
      CHECK_FALSE(prt::AtomicFile::IsTemporaryName(other));
    }
  }
}
