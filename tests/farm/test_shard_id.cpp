// --shard's value: I/N as given, or the task's index and count as a scheduler's environment gives
// them (farm/shard_id.h), each refusal naming what it read.
#include <doctest/doctest.h>

#include <map>
#include <string>

#include "core/error.h"
#include "farm/shard_id.h"
#include "tests/test_support.h"

namespace prt {
namespace {

/// An environment holding `vars` only.
EnvLookup With(std::map<std::string, std::string> vars) {
  return [vars = std::move(vars)](const char* name) -> const char* {
    const auto it = vars.find(name);
    return it == vars.end() ? nullptr : it->second.c_str();
  };
}

std::string Refusal(const std::string& value, const EnvLookup& env) {
  return test::ErrorMessage([&] { ParseShard(value, env); });
}

}  // namespace

TEST_SUITE("farm") {
TEST_CASE("--shard I/N: 0-based index below the count, from the option alone") {
  const EnvLookup slurm = With({{"SLURM_ARRAY_TASK_ID", "5"}, {"SLURM_ARRAY_TASK_COUNT", "9"}});
  const ShardId s = ParseShard("2/7", slurm);  // the environment is not read for I/N
  CHECK(s.index == 2);
  CHECK(s.count == 7);
  CHECK(s.source == "--shard 2/7");
  CHECK(ParseShard("0/1", slurm).count == 1);
  // Five digits in a shard's file name: 99999 shards at most.
  CHECK(ParseShard("99998/99999", slurm).index == 99998);
  for (const char* bad : {"3/3", "4/3", "0/0", "-1/3", "1/", "/3", "1", "a/3", "1/3x", "1/100000", "", "1//3", "1.0/3",
                          "1/1000000000000"}) {
    CAPTURE(bad);
    CHECK(Refusal(bad, slurm).find("--shard " + std::string(bad)) == 0);
    CHECK(Refusal(bad, slurm).find("expected I/N") != std::string::npos);
  }
}

TEST_CASE("--shard auto: a Slurm array task's index and count, by its count or its min and max") {
  ShardId s = ParseShard("auto", With({{"SLURM_ARRAY_TASK_ID", "3"}, {"SLURM_ARRAY_TASK_COUNT", "16"}}));
  CHECK(s.index == 3);
  CHECK(s.count == 16);
  CHECK(s.source == "SLURM_ARRAY_TASK_ID=3 of SLURM_ARRAY_TASK_COUNT=16");
  // An array 1-8: the first task is shard 0.
  s = ParseShard("auto", With({{"SLURM_ARRAY_TASK_ID", "1"}, {"SLURM_ARRAY_TASK_MIN", "1"}, {"SLURM_ARRAY_TASK_MAX", "8"},
                               {"SLURM_ARRAY_TASK_COUNT", "8"}}));
  CHECK(s.index == 0);
  CHECK(s.count == 8);
  s = ParseShard("auto", With({{"SLURM_ARRAY_TASK_ID", "12"}, {"SLURM_ARRAY_TASK_MIN", "10"}, {"SLURM_ARRAY_TASK_MAX", "13"}}));
  CHECK(s.index == 2);
  CHECK(s.count == 4);
  // An array with a step (0-14:2 has 8 tasks over 15 indices): no block per task fits it.
  CHECK(Refusal("auto", With({{"SLURM_ARRAY_TASK_ID", "2"}, {"SLURM_ARRAY_TASK_MIN", "0"}, {"SLURM_ARRAY_TASK_MAX", "14"},
                              {"SLURM_ARRAY_TASK_COUNT", "8"}}))
            .find("without a step") != std::string::npos);
  // An id without a count: the count must be given.
  CHECK(Refusal("auto", With({{"SLURM_ARRAY_TASK_ID", "2"}})).find("--shard auto/N") != std::string::npos);
  CHECK(Refusal("auto", With({{"SLURM_ARRAY_TASK_ID", "x"}, {"SLURM_ARRAY_TASK_COUNT", "4"}})).find("SLURM_ARRAY_TASK_ID=x") !=
        std::string::npos);
  CHECK(Refusal("auto", With({{"SLURM_ARRAY_TASK_ID", "4"}, {"SLURM_ARRAY_TASK_COUNT", "4"}})).find("shard 4 of 4") !=
        std::string::npos);
}

TEST_CASE("--shard auto/N: a Kubernetes Indexed Job's index with the count given, checked against Slurm's own") {
  ShardId s = ParseShard("auto/5", With({{"JOB_COMPLETION_INDEX", "4"}}));
  CHECK(s.index == 4);
  CHECK(s.count == 5);
  CHECK(s.source == "JOB_COMPLETION_INDEX=4 of --shard auto/5");
  CHECK(Refusal("auto/5", With({{"JOB_COMPLETION_INDEX", "5"}})).find("shard 5 of 5") != std::string::npos);
  CHECK(Refusal("auto", With({{"JOB_COMPLETION_INDEX", "1"}})).find("gives no task count") != std::string::npos);
  // Slurm's id with the count given, and a count that contradicts Slurm's.
  CHECK(ParseShard("auto/6", With({{"SLURM_ARRAY_TASK_ID", "5"}})).index == 5);
  CHECK(Refusal("auto/6", With({{"SLURM_ARRAY_TASK_ID", "1"}, {"SLURM_ARRAY_TASK_COUNT", "4"}})).find("says 4 tasks") !=
        std::string::npos);
  CHECK(Refusal("auto", With({})).find("no task index in the environment") != std::string::npos);
  CHECK(Refusal("auto/x", With({{"JOB_COMPLETION_INDEX", "1"}})).find("expected I/N") != std::string::npos);
}

}  // TEST_SUITE

}  // namespace prt
