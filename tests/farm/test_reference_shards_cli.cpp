// prt reference --shard I/N and prt merge, as processes: the merged folder holds what one
// reference writes (reference.txt, reference.png, the list), byte for byte, shadowed, with
// bounces and glossy; a set of shards whose light changed since its tasks ran, or that misses
// one, is refused with nothing final written.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include "tests/test_process.h"

namespace prt {
namespace {

namespace fs = std::filesystem;
using test::Q;

/// The reference of `options` as `count` tasks into `dir` (REQUIREd to succeed).
void Tasks(const std::string& options, const std::string& dir, int count) {
  for (int i = 0; i < count; ++i) {
    const test::RunResult task = test::RunPrt("reference" + options + " --out " + Q(dir) + " --shard " +
                                              std::to_string(i) + "/" + std::to_string(count) + " --quiet");
    REQUIRE_MESSAGE(task.exit_code == 0, task.err);
  }
}

}  // namespace

TEST_SUITE("farm") {
TEST_CASE("farm: a reference's shards and merge write what one reference writes, byte for byte") {
  const std::string scene = test::SmallSceneOption("reference_shards_scene") + " --reference-samples 64";  // 241 vertices
  const char* cases[] = {"", " --transport interreflection --bounces 2", " --material phong:10,0.15"};
  for (const char* options : cases) {
    CAPTURE(options);
    const std::string one = test::ScratchDir("reference_shards_one"), farm = test::ScratchDir("reference_shards_farm");
    const test::RunResult run = test::RunPrt("reference" + scene + options + " --out " + Q(one) + " --quiet");
    REQUIRE_MESSAGE(run.exit_code == 0, run.err);
    Tasks(scene + options, farm, 3);
    CHECK_FALSE(fs::exists(farm + "/reference.txt"));  // a task writes its shard alone
    const test::RunResult merge = test::RunPrt("merge " + Q(farm));
    REQUIRE_MESSAGE(merge.exit_code == 0, merge.err);
    CHECK(merge.err.find("reference: assembled from 3 shards (241 vertices)") != std::string::npos);
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
  fs::remove(dir + "/reference.shard-00001-of-00003");
  test::RunResult r = test::RunPrt("merge " + Q(dir));
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
  CHECK_FALSE(fs::exists(dir + "/reference.txt"));
  CHECK_FALSE(fs::exists(dir + "/reference.png"));
  CHECK(fs::exists(dir + "/reference.shard-00000-of-00003"));  // kept for a retry
  // A bad --shard is a usage error before any work.
  r = test::RunPrt("reference" + scene + " --out " + Q(dir + "/x") + " --shard 3/3");
  CHECK(r.exit_code == 2);
  CHECK_FALSE(fs::exists(dir + "/x"));
}
}  // TEST_SUITE

}  // namespace prt
