// A farm job's shards assembled (farm/assemble_shards.h) and the shard file itself
// (precompute_io/transport_shard.h): the rows in order, and every way a set of shards can be
// wrong refused with the file's name and reason before anything is assembled.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "core/error.h"
#include "farm/assemble_shards.h"
#include "farm/vertex_blocks.h"
#include "precompute_io/transport_shard.h"
#include "sh/coeffs.h"
#include "tests/test_support.h"

namespace prt {
namespace {

namespace fs = std::filesystem;
const char* kCache = "transport.cache";

/// A transport of `vertices` vertices at lmax 1 whose every float is distinct (its index + 1),
/// with matrices when asked.
Transport Numbered(std::size_t vertices, bool matrices) {
  Transport t;
  t.lmax = 1;
  t.channels = 3;
  t.vertices = vertices;
  t.coeffs.resize(vertices * 3 * 4);
  for (std::size_t i = 0; i < t.coeffs.size(); ++i) t.coeffs[i] = float(i + 1);
  if (matrices) {
    t.matrices.resize(vertices * 3 * 16);
    for (std::size_t i = 0; i < t.matrices.size(); ++i) t.matrices[i] = -float(i + 1);
  }
  return t;
}

/// Writes `whole` as `count` shards into `dir` (made by `command`, with `key`); returns their paths.
std::vector<std::string> WriteShards(const std::string& dir, const Transport& whole, int count, std::uint64_t key = 42,
                                     const std::vector<std::string>& command = {"--out", "x", "--lmax", "1"}) {
  std::vector<std::string> paths;
  const std::vector<std::uint64_t> work(whole.vertices, 1);
  for (int i = 0; i < count; ++i) {
    TransportShard s;
    s.index = i;
    s.count = count;
    s.key = key;
    s.command = command;
    s.block = BlockOf(work, i, count);
    s.rows = BlockRows(whole, s.block);
    paths.push_back(dir + "/" + ShardFileName(kCache, i, count));
    WriteTransportShard(paths.back(), s);
  }
  return paths;
}

std::string Refusal(const std::string& dir) {
  return test::ErrorMessage([&] { AssembleShards(dir, kCache); });
}

std::string Bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void Put(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

}  // namespace

TEST_SUITE("farm") {
TEST_CASE("shard file names: index and count in five digits, read back; other names are not shards") {
  CHECK(ShardFileName(kCache, 3, 16) == "transport.cache.shard-00003-of-00016");
  int i = -1, n = -1;
  CHECK(IsShardFileName("transport.cache.shard-00003-of-00016", kCache, i, n));
  CHECK(i == 3);
  CHECK(n == 16);
  for (const char* other : {"transport.cache", "transport.cache.shard-0003-of-00016", "wavelet.cache.shard-00003-of-00016",
                            "transport.cache.shard-00003-of-0016x", "transport.cache.shard-00003_of_00016",
                            ".transport.cache.shard-00003-of-00016.prt-tmp123_0",
                            "transport.cache.shard-00000-of-00000", "transport.cache.shard-00016-of-00016"})
    CHECK_FALSE(IsShardFileName(other, kCache, i, n));
}

TEST_CASE("shards assembled: every row in order, the command and key of the job, for any count") {
  for (const bool matrices : {false, true}) {
    for (const int count : {1, 3, 7}) {
      CAPTURE(matrices);
      CAPTURE(count);
      const std::string dir = test::ScratchDir("assemble_" + std::to_string(count) + (matrices ? "m" : ""));
      const Transport whole = Numbered(50, matrices);
      const std::vector<std::string> paths = WriteShards(dir, whole, count, 99, {"--out", dir, "--seed", "3"});
      // A killed task's temporary file beside them is not a shard.
      Put(dir + "/." + ShardFileName(kCache, 0, count) + AtomicFile::kTemporaryTag + "999999_0", "partial");
      const AssembledShards a = AssembleShards(dir, kCache);
      CHECK(a.count == count);
      CHECK(a.key == 99);
      CHECK(a.command == std::vector<std::string>{"--out", dir, "--seed", "3"});
      CHECK(a.files == paths);
      CHECK(a.transport.vertices == 50);
      CHECK(a.transport.channels == 3);
      CHECK(a.transport.lmax == 1);
      CHECK(a.transport.coeffs == whole.coeffs);
      CHECK(a.transport.matrices == whole.matrices);
      CHECK(a.transport.glossy.empty());
    }
  }
}

TEST_CASE("shards refused: missing, damaged, renamed, foreign or of another job, each by name and reason") {
  const Transport whole = Numbered(40, true);
  const auto fresh = [&](const std::string& name) {
    const std::string dir = test::ScratchDir("refuse_" + name);
    return std::make_pair(dir, WriteShards(dir, whole, 4));
  };
  {
    auto [dir, paths] = fresh("missing");
    fs::remove(paths[1]);
    fs::remove(paths[3]);
    const std::string why = Refusal(dir);
    CHECK(why.find("shards 1, 3 of 4 missing") != std::string::npos);
    CHECK(why.find(dir) == 0);
  }
  {
    const std::string dir = test::ScratchDir("refuse_none");
    CHECK(Refusal(dir).find("no shards of transport.cache") != std::string::npos);
  }
  {
    auto [dir, paths] = fresh("truncated");
    const std::string bytes = Bytes(paths[2]);
    for (const std::size_t keep : {std::size_t(0), std::size_t(10), bytes.size() / 2, bytes.size() - 1}) {
      Put(paths[2], bytes.substr(0, keep));
      const std::string why = Refusal(dir);
      CAPTURE(keep);
      CHECK(why.find(paths[2] + ": ") == 0);
      CHECK(why.find("run task 2 again") != std::string::npos);
    }
    Put(paths[2], bytes + "x");
    CHECK(Refusal(dir).find("truncated or oversized") != std::string::npos);
  }
  {
    auto [dir, paths] = fresh("corrupted");
    std::string bytes = Bytes(paths[1]);
    bytes[bytes.size() - 3] ^= 0x10;  // a matrix entry
    Put(paths[1], bytes);
    CHECK(Refusal(dir).find(paths[1] + ": checksum mismatch") == 0);
  }
  {
    // A letter of the command's last word ("--lmax 1", after the first words and the header):
    // the checksum covers every word.
    auto [dir, paths] = fresh("command");
    std::string bytes = Bytes(paths[2]);
    const std::size_t word = bytes.find(std::string("--lmax") + '\0' + "1");
    REQUIRE(word != std::string::npos);
    bytes[word + 7] = '2';
    Put(paths[2], bytes);
    CHECK(Refusal(dir).find(paths[2] + ": checksum mismatch") == 0);
  }
  {
    auto [dir, paths] = fresh("renamed");
    fs::rename(paths[2], dir + "/moved");
    fs::rename(paths[1], paths[2]);  // shard 1 under shard 2's name, and no shard 1
    CHECK(Refusal(dir).find("shard 1 of 4 missing") != std::string::npos);
    fs::copy_file(paths[2], paths[1]);  // shard 1 twice, no shard 2
    CHECK(Refusal(dir).find(paths[2] + ": holds shard 1 of 4, not the one its name says") == 0);
  }
  {
    auto [dir, paths] = fresh("foreign");
    const std::string other = test::ScratchDir("refuse_foreign_other");
    const std::vector<std::string> theirs = WriteShards(other, whole, 4, 43);  // another mesh or options
    fs::copy_file(theirs[3], paths[3], fs::copy_options::overwrite_existing);
    CHECK(Refusal(dir).find(paths[3] + ": made from another mesh or options than shard 0") == 0);
    const std::vector<std::string> command = WriteShards(other, whole, 4, 42, {"--out", "x", "--lmax", "2"});
    fs::copy_file(command[3], paths[3], fs::copy_options::overwrite_existing);
    CHECK(Refusal(dir).find(paths[3] + ": made by another command than shard 0") == 0);
  }
  {
    auto [dir, paths] = fresh("counts");
    WriteShards(dir, whole, 5);  // a second job's shards beside the first's
    CHECK(Refusal(dir).find("beside shards of") != std::string::npos);
  }
}

}  // TEST_SUITE

}  // namespace prt
