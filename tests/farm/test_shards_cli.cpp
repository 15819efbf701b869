// prt precompute --shard I/N and prt merge as a farm job runs them, as processes: the merged
// folder holds every file one run writes, the same bytes; each refusal comes before anything
// final is written; a task killed mid-shard leaves nothing a merge would take, and running it
// again completes the set.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <unistd.h>

#include "core/atomic_file.h"
#include "tests/test_process.h"

namespace prt {
namespace {

namespace fs = std::filesystem;
using test::Q;

/// The task `index` of `count` of `options` into `dir`.
test::RunResult Task(const std::string& options, const std::string& dir, int index, int count) {
  return test::RunPrt("precompute" + options + " --out " + Q(dir) + " --shard " + std::to_string(index) + "/" +
                      std::to_string(count) + " --quiet");
}

/// Runs `options` as `count` shards and a merge into `dir`; REQUIREs each to succeed.
void Farm(const std::string& options, const std::string& dir, int count) {
  for (int i = 0; i < count; ++i) {
    const test::RunResult task = Task(options, dir, i, count);
    REQUIRE_MESSAGE(task.exit_code == 0, task.err);
  }
  const test::RunResult merge = test::RunPrt("merge " + Q(dir) + " --quiet");
  REQUIRE_MESSAGE(merge.exit_code == 0, merge.err);
}

}  // namespace

TEST_SUITE("farm") {
TEST_CASE("farm: shards and a merge write the folder one precompute writes, byte for byte, every mode and part") {
  const std::string scene = test::SmallSceneOption("farm_bytes");  // 241 vertices: no count below divides it
  const char* cases[] = {" --transport unshadowed", " --samples 128", " --lmax 3 --samples 64 --sampler stratified",
                         " --samples 64 --material phong:10,0.15 --cpca 2,1"};
  for (const char* options : cases) {
    CAPTURE(options);
    const std::string one = test::ScratchDir("farm_one"), farm = test::ScratchDir("farm_shards");
    const test::RunResult run = test::RunPrt("precompute" + scene + options + " --out " + Q(one) + " --quiet");
    REQUIRE_MESSAGE(run.exit_code == 0, run.err);
    Farm(scene + options, farm, 3);
    const auto expected = test::FolderFiles(one), got = test::FolderFiles(farm);
    CHECK(expected.count("transport.cache") == 1);
    CHECK(got.size() == expected.size());  // the shard files removed
    for (const auto& [name, bytes] : expected) {
      CAPTURE(name);
      REQUIRE(got.count(name) == 1);
      CHECK(got.at(name) == bytes);
    }
  }
}

TEST_CASE("farm: interreflection's direct pass and each bounce as stages of the same tasks, merged: one run's bytes") {
  const std::string scene = test::SmallSceneOption("farm_bounces");  // coloured: three channels
  struct Case {
    const char* options;
    int bounces;
    int stages;  // the merges that do work: the direct pass, then each bounce computed
  };
  const Case cases[] = {{" --transport interreflection --bounces 2 --samples 128", 2, 3},
                        // So dark a scene that bounce 1 adds 7e-5 of the direct energy, under the
                        // 1e-4 that ends the bounces (transport.h): bounce 2 is not computed.
                        {" --transport interreflection --bounces 2 --albedo 0.001,0.001,0.001 --samples 64", 2, 2}};
  for (const Case& c : cases) {
    CAPTURE(c.options);
    const std::string one = test::ScratchDir("farm_bounces_one"), farm = test::ScratchDir("farm_bounces_shards");
    REQUIRE(test::RunPrt("precompute" + scene + c.options + " --out " + Q(one) + " --quiet").exit_code == 0);
    // Every stage of prt farm's chain, each named (--bounce-stage K), as its jobs run them.
    for (int stage = 0; stage <= c.bounces; ++stage) {
      CAPTURE(stage);
      for (int i = 0; i < 3; ++i) {
        const test::RunResult task = test::RunPrt("precompute" + scene + c.options + " --out " + Q(farm) + " --shard " +
                                                  std::to_string(i) + "/3 --bounce-stage " + std::to_string(stage));
        REQUIRE_MESSAGE(task.exit_code == 0, task.err);
        // Once the bounces have ended, the tasks find nothing to do.
        CHECK((task.err.find("nothing to do") != std::string::npos) == (stage >= c.stages));
      }
      const test::RunResult merge = test::RunPrt("merge " + Q(farm) + " --bounce-stage " + std::to_string(stage));
      REQUIRE_MESSAGE(merge.exit_code == 0, merge.err);
      // The task run again once its stage is merged: nothing to do, nothing written.
      const test::RunResult again = test::RunPrt("precompute" + scene + c.options + " --out " + Q(farm) +
                                                 " --shard 0/3 --bounce-stage " + std::to_string(stage));
      CHECK(again.exit_code == 0);
      CHECK(again.err.find("nothing to do") != std::string::npos);
      // The folder holds one run's files from the last stage's merge on, and not before.
      CHECK(fs::exists(farm + "/transport.txt") == (stage + 1 >= c.stages));
      CHECK((merge.err.find("nothing to merge") != std::string::npos) == (stage >= c.stages));
    }
    CHECK(test::FolderFiles(farm) == test::FolderFiles(one));  // the last stage's merge removed what an early end kept
  }
}

TEST_CASE("farm: interreflection whose first block sees no lit surface still bounces: every block's hits count") {
  // A grid of 3,600 vertices far from the small scene, first in the file, open to the sky: the
  // first of three blocks holds only grid vertices, whose rays hit nothing. The small scene after
  // it has bounces.
  const std::string dir = test::ScratchDir("farm_first_block_dark");
  const std::string small = test::WriteSmallScene(dir);
  std::string obj;
  constexpr int kSide = 60;
  for (int z = 0; z < kSide; ++z)
    for (int x = 0; x < kSide; ++x) obj += "v " + std::to_string(100 + x * 0.1) + " 0 " + std::to_string(z * 0.1) + "\n";
  for (int z = 0; z + 1 < kSide; ++z)
    for (int x = 0; x + 1 < kSide; ++x) {
      const int a = z * kSide + x + 1, b = a + 1, c = a + kSide, d = c + 1;  // counter-clockwise seen from above
      obj += "f " + std::to_string(a) + " " + std::to_string(c) + " " + std::to_string(b) + "\n";
      obj += "f " + std::to_string(b) + " " + std::to_string(c) + " " + std::to_string(d) + "\n";
    }
  std::ifstream in(small);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("f ", 0) == 0) {  // its vertex indices after the grid's ("f a//n b//n c//n")
      std::istringstream words(line.substr(2));
      line = "f";
      for (std::string w; words >> w;) {
        const std::size_t slash = w.find('/');
        line += " " + std::to_string(std::stoi(w.substr(0, slash)) + kSide * kSide) +
                (slash == std::string::npos ? "" : w.substr(slash));
      }
    }
    if (line.rfind("mtllib", 0) != 0 && line.rfind("usemtl", 0) != 0) obj += line + "\n";
  }
  const std::string mesh = dir + "/grid_and_scene.obj";
  std::ofstream(mesh) << obj;
  const std::string options = " --mesh " + Q(mesh) + " --transport interreflection --samples 64";
  const std::string one = test::ScratchDir("farm_first_block_dark_one"), farm = test::ScratchDir("farm_first_block_dark_farm");
  const test::RunResult run = test::RunPrt("precompute" + options + " --out " + Q(one));
  REQUIRE_MESSAGE(run.exit_code == 0, run.err);
  CHECK(run.err.find("no bounce pass") == std::string::npos);  // the one run has its bounce
  for (int stage = 0; stage < 2; ++stage) {
    for (int i = 0; i < 3; ++i) REQUIRE(Task(options, farm, i, 3).exit_code == 0);
    REQUIRE(test::RunPrt("merge " + Q(farm) + " --quiet").exit_code == 0);
  }
  CHECK(test::FolderFiles(farm) == test::FolderFiles(one));
}

TEST_CASE("farm: interreflection's stages refuse a missing bounce shard, another job's state and a lost direct pass") {
  const std::string scene = test::SmallSceneOption("farm_bounces_refused_scene") + " --transport interreflection --samples 64";
  const std::string dir = test::ScratchDir("farm_bounces_refused");
  for (int i = 0; i < 3; ++i) REQUIRE(Task(scene, dir, i, 3).exit_code == 0);
  REQUIRE(test::RunPrt("merge " + Q(dir) + " --quiet").exit_code == 0);  // the direct pass assembled
  for (int i : {0, 2}) REQUIRE(Task(scene, dir, i, 3).exit_code == 0);   // bounce 1 without task 1
  test::RunResult r = test::RunPrt("merge " + Q(dir));
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("shard 1 of 3 missing") != std::string::npos);
  CHECK_FALSE(fs::exists(dir + "/transport.txt"));
  // The same tasks with another seed: the state is another job's.
  r = Task(scene + " --seed 5", dir, 1, 3);
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("transport.cache.bounces: the bounces of another job") != std::string::npos);
  // Task 1's direct pass lost: its bounce cannot be gathered.
  fs::remove(dir + "/transport.cache.hits.shard-00001-of-00003");
  r = Task(scene, dir, 1, 3);
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("transport.cache.hits.shard-00001-of-00003: ") != std::string::npos);
  CHECK(r.err.find("this task's direct pass") != std::string::npos);
}

TEST_CASE("farm: the merge of a folder moved since its tasks ran, from another folder, with the mesh named relatively") {
  const std::string scene_dir = test::ScratchDir("farm_moved_scene");
  test::WriteSmallScene(scene_dir);
  const std::string before = test::ScratchDir("farm_moved_before"), one = test::ScratchDir("farm_moved_one");
  const std::string after = before + "_after";
  fs::remove_all(after);
  // The tasks in the scene's folder, the mesh by its name there (one written ./small_scene.obj).
  for (int i = 0; i < 2; ++i) {
    const std::string mesh = i == 0 ? "small_scene.obj" : "./small_scene.obj";
    REQUIRE(test::RunCommand("cd " + Q(scene_dir) + " && " + Q(test::PrtBinary()) + " precompute --mesh " + mesh +
                             " --samples 64 --out " + Q(before) + " --shard " + std::to_string(i) + "/2 --quiet")
                .exit_code == 0);
  }
  fs::rename(before, after);
  const test::RunResult merge = test::RunCommand("cd / && " + Q(test::PrtBinary()) + " merge " + Q(after) + " --quiet");
  REQUIRE_MESSAGE(merge.exit_code == 0, merge.err);
  CHECK_FALSE(fs::exists(before));  // nothing written where the tasks wrote
  REQUIRE(test::RunPrt("precompute --mesh " + Q(scene_dir + "/small_scene.obj") + " --samples 64 --out " + Q(one) +
                       " --quiet").exit_code == 0);
  CHECK(test::FolderFiles(after) == test::FolderFiles(one));
  fs::remove_all(after);
}

TEST_CASE("farm: a shard count or index that cannot be, and a glossy interreflection, refused before any work") {
  const std::string dir = test::ScratchDir("farm_refused");
  const std::string scene = test::SmallSceneOption("farm_refused_scene");
  test::RunResult r = Task(scene, dir, 3, 3);
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("prt: error: --shard 3/3: shard 3 of 3") == 0);
  r = test::RunPrt("precompute" + scene + " --out " + Q(dir) +
                   " --shard 0/2 --transport interreflection --albedo 0.5,0.5,0.5 --material phong:10,0.3");
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("--shard: not with --transport interreflection and a glossy material") != std::string::npos);
  r = test::RunCommand("env -u SLURM_ARRAY_TASK_ID -u JOB_COMPLETION_INDEX " + Q(test::PrtBinary()) + " precompute" + scene +
                       " --out " + Q(dir) + " --shard auto");
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("no task index in the environment") != std::string::npos);
  r = test::RunCommand("SLURM_ARRAY_TASK_ID=1 SLURM_ARRAY_TASK_COUNT=2 " + Q(test::PrtBinary()) + " precompute" + scene +
                       " --out " + Q(dir) + " --shard auto");
  CHECK(r.exit_code == 0);
  CHECK(fs::exists(dir + "/transport.cache.shard-00001-of-00002"));
  CHECK(r.err.find("SLURM_ARRAY_TASK_ID=1 of SLURM_ARRAY_TASK_COUNT=2") != std::string::npos);
  // More shards than vertices: refused once the mesh is read, nothing written.
  r = Task(scene, dir, 0, 242);
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("242 shards for 241 vertices") != std::string::npos);
  CHECK_FALSE(fs::exists(dir + "/transport.cache.shard-00000-of-00242"));
}

TEST_CASE("farm: an incomplete, foreign or stale set of shards is refused by merge with nothing final written") {
  const std::string scene_dir = test::ScratchDir("farm_merge_scene");
  const std::string scene = test::SmallSceneOption("farm_merge_scene");
  const std::string dir = test::ScratchDir("farm_merge");
  for (int i : {0, 2}) REQUIRE(Task(scene + " --samples 64", dir, i, 3).exit_code == 0);
  test::RunResult r = test::RunPrt("merge " + Q(dir));
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("shard 1 of 3 missing") != std::string::npos);
  // Shard 1 of a job with another seed: its command and its key differ.
  REQUIRE(Task(scene + " --samples 64 --seed 9", dir, 1, 3).exit_code == 0);
  r = test::RunPrt("merge " + Q(dir));
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("transport.cache.shard-00001-of-00003: made by another command than shard 0") != std::string::npos);
  // The right shard 1: then the mesh file changes before the merge (a stale set), one vertex
  // moved: the same vertex and triangle counts, another mesh.
  REQUIRE(Task(scene + " --samples 64", dir, 1, 3).exit_code == 0);
  const std::string mesh = scene.substr(scene.find('\'') + 1, scene.rfind('\'') - scene.find('\'') - 1);
  std::string obj;
  {
    std::ifstream in(mesh);
    obj.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::size_t v = obj.find("\nv ") + 3, end = obj.find(' ', v);
  REQUIRE(end != std::string::npos);
  obj.replace(v, end - v, std::to_string(std::stod(obj.substr(v, end - v)) + 0.01));  // the first vertex moved
  std::ofstream(mesh) << obj;
  r = test::RunPrt("merge " + Q(dir));
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("the shards were made from another mesh or other options") != std::string::npos);
  for (const char* final : {"light.txt", "transport.txt", "transport.cache", ".prt-outputs"}) {
    CAPTURE(final);
    CHECK_FALSE(fs::exists(dir + "/" + final));
  }
  CHECK(fs::exists(dir + "/transport.cache.shard-00001-of-00003"));  // kept for a retry
}

TEST_CASE("farm: a task killed mid-shard leaves no shard; run again, the set completes as one run") {
  const std::string scene = test::SmallSceneOption("farm_killed_scene") + " --samples 65536";
  const std::string dir = test::ScratchDir("farm_killed"), one = test::ScratchDir("farm_killed_one");
  REQUIRE(Task(scene, dir, 0, 2).exit_code == 0);
  // Task 1 stopped by SIGKILL, then by the scheduler's SIGTERM, each while it computes (on one
  // thread it takes over a second here): the exit status says the signal ended it (so it was
  // still running), and no file of it is left. --threads is not part of a shard's command.
  for (const char* signal : {"KILL", "TERM"}) {
    CAPTURE(signal);
    const test::RunResult killed = test::RunCommand(
        Q(test::PrtBinary()) + " precompute" + scene + " --out " + Q(dir) + " --shard 1/2 --threads 1 --quiet & pid=$!; sleep 0.3; kill -" +
        signal + " $pid; wait $pid; echo status=$?");
    CHECK(killed.out.find(std::string("status=") + (signal[0] == 'K' ? "137" : "143")) != std::string::npos);
    for (const fs::directory_entry& e : fs::directory_iterator(dir))
      CHECK(e.path().filename().string().find("shard-00001") == std::string::npos);
  }
  test::RunResult r = test::RunPrt("merge " + Q(dir));
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("shard 1 of 2 missing") != std::string::npos);
  // Run again on another number of threads, not quiet: neither is part of the shard's command.
  REQUIRE(test::RunPrt("precompute" + scene + " --out " + Q(dir) + " --shard 1/2 --threads 1").exit_code == 0);
  // What a task killed while writing its shard leaves (its temporary file): not a shard, and
  // gone after the merge.
  // Named with this test's own process, alive: not a temporary any run would sweep as its
  // writer's gone (a task on another machine may be alive), but one the merge removes.
  std::ofstream(dir + "/.transport.cache.shard-00001-of-00002" + AtomicFile::kTemporaryTag + std::to_string(::getpid()) +
                "_0")
      << "partial";
  REQUIRE(test::RunPrt("merge " + Q(dir) + " --quiet").exit_code == 0);
  REQUIRE(test::RunPrt("precompute" + scene + " --out " + Q(one) + " --quiet").exit_code == 0);
  CHECK(test::FolderFiles(dir) == test::FolderFiles(one));
}

}  // TEST_SUITE

}  // namespace prt
