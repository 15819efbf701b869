// prt render --shard I/N and prt merge, as processes: the merged folder holds what one render
// writes (frames, cache, --vertex-radiance, list), byte for byte, for every transport mode and
// the glossy material's fixed view and orbit; a render's tasks refuse what does not split.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include "tests/test_process.h"

namespace prt {
namespace {

namespace fs = std::filesystem;
using test::Q;

/// Runs `options` as a render of `count` shards and their merges into `dir`, interreflection's
/// stages (0 the direct pass, then each of `bounces`) each as prt farm's chain runs them.
void FarmRender(const std::string& options, const std::string& dir, int count, int bounces) {
  for (int stage = 0; stage <= bounces; ++stage) {
    CAPTURE(stage);
    const std::string named = bounces > 0 ? " --bounce-stage " + std::to_string(stage) : "";
    for (int i = 0; i < count; ++i) {
      const test::RunResult task = test::RunPrt("render" + options + " --out " + Q(dir) + " --shard " +
                                                std::to_string(i) + "/" + std::to_string(count) + named + " --quiet");
      REQUIRE_MESSAGE(task.exit_code == 0, task.err);
    }
    CHECK_FALSE(fs::exists(dir + "/frame_0000.png"));  // a task renders no frame
    const test::RunResult merge = test::RunPrt("merge " + Q(dir) + named + " --quiet");
    REQUIRE_MESSAGE(merge.exit_code == 0, merge.err);
  }
}

}  // namespace

TEST_SUITE("farm") {
TEST_CASE("farm: a render's shards and merge write the folder one render writes, byte for byte, every mode") {
  const std::string scene = test::SmallSceneOption("render_shards_scene") + " --frames 3 --size 40x30";  // 241 vertices
  struct Case {
    const char* options;
    int bounces;
  };
  const Case cases[] = {
      {" --transport unshadowed", 0},
      // Seen and hidden vertices cast different counts: blocks balanced by work, not count.
      {" --samples 128 --hidden-samples 16", 0},
      {" --samples 64 --material phong:10,0.15", 0},                 // vectors toward the fixed eye
      {" --samples 64 --material phong:10,0.15 --orbit 30", 0},      // transfer matrices, compressed
      {" --samples 64 --vertex-radiance radiance.txt --transport interreflection --bounces 1", 1},
  };
  for (const Case& c : cases) {
    CAPTURE(c.options);
    const std::string one = test::ScratchDir("render_shards_one"), farm = test::ScratchDir("render_shards_farm");
    // --vertex-radiance's file in each run's own folder.
    const auto in = [&c](const std::string& dir) {
      std::string options = c.options;
      const std::string file = "radiance.txt";
      if (const auto at = options.find(file); at != std::string::npos) options.replace(at, file.size(), Q(dir + "/" + file));
      return options;
    };
    const test::RunResult run = test::RunPrt("render" + scene + in(one) + " --out " + Q(one) + " --quiet");
    REQUIRE_MESSAGE(run.exit_code == 0, run.err);
    FarmRender(scene + in(farm), farm, 3, c.bounces);
    CHECK(test::FolderFiles(farm) == test::FolderFiles(one));  // the shard and stage files removed
  }
}

TEST_CASE("farm: a render's shards refuse a basis whose transport does not split and a view without transport") {
  const std::string dir = test::ScratchDir("render_shards_refused");
  test::RunResult r = test::RunPrt(test::QuickRender(dir + "/w", 2) + " --basis wavelet --shard 0/2");
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("--shard: --basis wavelet's transport does not split into vertex blocks") != std::string::npos);
  r = test::RunPrt(test::QuickRender(dir + "/l", 2) + " --view light --shard 0/2");
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("--view light computes no transport to split") != std::string::npos);
  CHECK_FALSE(fs::exists(dir + "/w"));
  CHECK_FALSE(fs::exists(dir + "/l"));
  // A render's shards and a precompute's in one folder: the merge names the command.
  const std::string mixed = test::ScratchDir("render_shards_mixed");
  const std::string scene = test::SmallSceneOption("render_shards_mixed_scene") + " --samples 64";
  REQUIRE(test::RunPrt("render" + scene + " --out " + Q(mixed) + " --shard 0/2 --quiet").exit_code == 0);
  REQUIRE(test::RunPrt("precompute" + scene + " --out " + Q(mixed) + " --shard 1/2 --quiet").exit_code == 0);
  r = test::RunPrt("merge " + Q(mixed));
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("made by another command than shard 0") != std::string::npos);
  CHECK_FALSE(fs::exists(mixed + "/frame_0000.png"));
}
}  // TEST_SUITE

}  // namespace prt
