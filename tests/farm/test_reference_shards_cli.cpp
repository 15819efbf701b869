// prt reference --shard I/N and prt merge, as processes: the merged folder holds what one
// reference writes (reference.txt, reference.png, the list), byte for byte, shadowed, with
// bounces and glossy; a set of shards whose light changed since its tasks ran, or that misses
// one, is refused with nothing final written.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/test_process.h"

namespace prt {
namespace {

namespace fs = std::filesystem;
using test::Q;

/// The reference of `options` as `count` tasks into `dir` (REQUIREd to succeed); returns the
/// rays they traced, summed from their summaries.
unsigned long long Tasks(const std::string& options, const std::string& dir, int count) {
  unsigned long long rays = 0;
  for (int i = 0; i < count; ++i) {
    const test::RunResult task = test::RunPrt("reference" + options + " --out " + Q(dir) + " --shard " +
                                              std::to_string(i) + "/" + std::to_string(count));
    REQUIRE_MESSAGE(task.exit_code == 0, task.err);
    const std::size_t at = task.err.find("reference: ");
    REQUIRE(at != std::string::npos);
    rays += std::stoull(task.err.substr(at + 11));
  }
  return rays;
}

/// The figures of a reference's summary line: its rays and its RMS error and radiance (the
/// seconds between them left out).
std::string Figures(const std::string& err) {
  const std::size_t line = err.find("lattice directions per vertex in two halves, ");
  REQUIRE(line != std::string::npos);
  const std::size_t rays = line + 45, seconds = err.find(" [", rays), rms = err.find("]; estimated", seconds);
  return err.substr(rays, seconds - rays) + err.substr(rms, err.find('\n', rms) - rms);
}

void Flip(const std::string& path, std::uintmax_t at) {
  std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
  f.seekg(std::streamoff(at));
  char c = 0;
  f.read(&c, 1);
  f.seekp(std::streamoff(at));
  c ^= 0x10;
  f.write(&c, 1);
}

}  // namespace

TEST_SUITE("farm") {
TEST_CASE("farm: a reference's shards and merge write what one reference writes, byte for byte") {
  const std::string scene = test::SmallSceneOption("reference_shards_scene") + " --reference-samples 64";  // 241 vertices
  const char* cases[] = {"", " --transport interreflection --bounces 2", " --material phong:10,0.15"};
  for (const char* options : cases) {
    CAPTURE(options);
    const std::string one = test::ScratchDir("reference_shards_one"), farm = test::ScratchDir("reference_shards_farm");
    const test::RunResult run = test::RunPrt("reference" + scene + options + " --out " + Q(one));
    REQUIRE_MESSAGE(run.exit_code == 0, run.err);
    // Each task traces its block's rays alone: together, one run's.
    const unsigned long long rays = Tasks(scene + options, farm, 3);
    CHECK(std::to_string(rays) + " rays" == Figures(run.err).substr(0, Figures(run.err).find(" rays") + 5));
    CHECK_FALSE(fs::exists(farm + "/reference.txt"));  // a task writes its shard alone
    const test::RunResult merge = test::RunPrt("merge " + Q(farm));
    REQUIRE_MESSAGE(merge.exit_code == 0, merge.err);
    CHECK(merge.err.find("reference: assembled from 3 shards (241 vertices)") != std::string::npos);
    // The summary's rays and RMS figures are one run's, every vertex counted.
    CHECK(Figures(merge.err) == Figures(run.err));
    CHECK(test::FolderFiles(farm) == test::FolderFiles(one));  // the shards removed
  }
}

TEST_CASE("farm: a reference's shards missing one, or made under a light changed since, refused by merge") {
  const std::string samples = test::ScratchDir("reference_shards_samples");
  REQUIRE(test::RunPrt("sample-files --out " + Q(samples) + " --quiet").exit_code == 0);
  const std::string scene = test::SmallSceneOption("reference_shards_refused_scene") + " --reference-samples 16 --env " +
                            Q(samples + "/sky_cubemap");
  const std::string dir = test::ScratchDir("reference_shards_refused");
  Tasks(scene, dir, 3);
  const std::string one = dir + "/reference.shard-00001-of-00003";
  const std::string whole = test::FolderFiles(dir).at("reference.shard-00001-of-00003");
  // A bit flipped in the last row's error, then a byte appended: refused, named.
  Flip(one, fs::file_size(one) - 1);
  test::RunResult r = test::RunPrt("merge " + Q(dir));
  CHECK(r.exit_code == 1);
  CHECK(r.err.find(one + ": checksum mismatch (corrupted)") != std::string::npos);
  std::ofstream(one, std::ios::binary) << whole << 'x';
  r = test::RunPrt("merge " + Q(dir));
  CHECK(r.exit_code == 1);
  CHECK(r.err.find(one + ": truncated or oversized") != std::string::npos);
  fs::remove(one);
  r = test::RunPrt("merge " + Q(dir));
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("shard 1 of 3 missing") != std::string::npos);
  // The task again, then two faces of the cubemap swapped: the same command, another light.
  REQUIRE(test::RunPrt("reference" + scene + " --out " + Q(dir) + " --shard 1/3 --quiet").exit_code == 0);
  const std::string faces = samples + "/sky_cubemap/";
  fs::rename(faces + "posx.hdr", faces + "swap.hdr");
  fs::rename(faces + "negx.hdr", faces + "posx.hdr");
  fs::rename(faces + "swap.hdr", faces + "negx.hdr");
  r = test::RunPrt("merge " + Q(dir));
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("the shards were made from another mesh, light or options") != std::string::npos);
  // Task 2 run again under the changed light: the same command, another key than shard 0's.
  REQUIRE(test::RunPrt("reference" + scene + " --out " + Q(dir) + " --shard 2/3 --quiet").exit_code == 0);
  r = test::RunPrt("merge " + Q(dir));
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("reference.shard-00002-of-00003: made from another mesh, light or options than shard 0") !=
        std::string::npos);
  CHECK_FALSE(fs::exists(dir + "/reference.txt"));
  CHECK_FALSE(fs::exists(dir + "/reference.png"));
  CHECK(fs::exists(dir + "/reference.shard-00000-of-00003"));  // kept for a retry
  // A bad --shard is a usage error before any work.
  r = test::RunPrt("reference" + scene + " --out " + Q(dir + "/x") + " --shard 3/3");
  CHECK(r.exit_code == 2);
  CHECK_FALSE(fs::exists(dir + "/x"));
}

TEST_CASE("farm: a reference's merge with --keep-shards keeps them; without, they go") {
  const std::string scene = test::SmallSceneOption("reference_shards_keep_scene") + " --reference-samples 8";
  const std::string dir = test::ScratchDir("reference_shards_keep");
  Tasks(scene, dir, 2);
  REQUIRE(test::RunPrt("merge " + Q(dir) + " --keep-shards --quiet").exit_code == 0);
  CHECK(fs::exists(dir + "/reference.txt"));
  CHECK(fs::exists(dir + "/reference.shard-00000-of-00002"));
  CHECK(fs::exists(dir + "/reference.shard-00001-of-00002"));
  REQUIRE(test::RunPrt("merge " + Q(dir) + " --quiet").exit_code == 0);
  CHECK_FALSE(fs::exists(dir + "/reference.shard-00000-of-00002"));
  CHECK_FALSE(fs::exists(dir + "/reference.shard-00001-of-00002"));
}
}  // TEST_SUITE

}  // namespace prt
