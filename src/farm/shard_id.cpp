#include "farm/shard_id.h"

#include <algorithm>
#include <cstdlib>
#include <optional>

#include "core/error.h"

namespace prt {
namespace {

/// A whole number 0..kMaxShards written in `text` alone, or nullopt.
std::optional<long> Whole(const std::string& text) {
  constexpr std::size_t kDigits = 6;  // more than any count allowed: a longer number is refused unread
  if (text.empty() || text.size() > kDigits || text.find_first_not_of("0123456789") != std::string::npos)
    return std::nullopt;
  const long n = std::strtol(text.c_str(), nullptr, 10);
  if (n > kMaxShards) return std::nullopt;
  return n;
}

/// The variable `name` as a whole number, nullopt when unset; Error when set to anything else.
std::optional<long> Variable(const EnvLookup& env, const char* name) {
  const char* value = env(name);
  if (value == nullptr) return std::nullopt;
  const auto n = Whole(value);
  if (!n) throw Error(std::string("--shard auto: ") + name + "=" + value + " is not a whole number 0.." + std::to_string(kMaxShards));
  return n;
}

const std::string kExpected = "(expected I/N with 0 <= I < N <= " + std::to_string(kMaxShards) + ", auto, or auto/N)";

/// The index and count Slurm gives an array task, if it is one.
std::optional<ShardId> FromSlurm(const EnvLookup& env) {
  const auto id = Variable(env, "SLURM_ARRAY_TASK_ID");
  if (!id) return std::nullopt;
  // -1: unset (plain numbers: the compiler cannot follow optionals through these branches)
  const long count = Variable(env, "SLURM_ARRAY_TASK_COUNT").value_or(-1);
  const long min = Variable(env, "SLURM_ARRAY_TASK_MIN").value_or(-1);
  const long max = Variable(env, "SLURM_ARRAY_TASK_MAX").value_or(-1);
  ShardId s;
  s.index = static_cast<int>(*id - std::max(min, 0L));
  s.source = "SLURM_ARRAY_TASK_ID=" + std::to_string(*id);
  if (min >= 0 && max >= 0) {
    const long span = max - min + 1;
    if (count >= 0 && count != span)
      throw Error("--shard auto: the Slurm array " + std::to_string(min) + "-" + std::to_string(max) + " has " +
                  std::to_string(count) + " tasks, not one per index (expected an array without a step, e.g. --array=0-" +
                  std::to_string(count - 1) + ")");
    s.count = static_cast<int>(span);
    s.source += " of SLURM_ARRAY_TASK_MIN=" + std::to_string(min) + "..SLURM_ARRAY_TASK_MAX=" + std::to_string(max);
  } else if (count >= 0) {
    s.count = static_cast<int>(count);
    s.source += " of SLURM_ARRAY_TASK_COUNT=" + std::to_string(count);
  } else {
    s.count = 0;  // the count must be given
  }
  return s;
}

void CheckRange(const ShardId& s, const std::string& what) {
  if (s.count < 1 || s.index < 0 || s.index >= s.count)
    throw Error(what + ": shard " + std::to_string(s.index) + " of " + std::to_string(s.count) + " " + kExpected);
}

}  // namespace

ShardId ParseShard(const std::string& value, const EnvLookup& env) {
  const std::size_t slash = value.find('/');
  const std::string head = value.substr(0, slash);
  // -1: no count given
  const long count = slash == std::string::npos ? -1 : Whole(value.substr(slash + 1)).value_or(-2);
  if (count == -2) throw Error("--shard " + value + ": " + kExpected);
  if (head != "auto") {
    const auto index = Whole(head);
    if (!index || count < 0) throw Error("--shard " + value + ": " + kExpected);
    ShardId s{static_cast<int>(*index), static_cast<int>(count), "--shard " + value};
    CheckRange(s, "--shard " + value);
    return s;
  }
  std::optional<ShardId> s = FromSlurm(env);
  if (!s) {
    const auto k8s = Variable(env, "JOB_COMPLETION_INDEX");
    if (!k8s)
      throw Error("--shard " + value +
                  ": no task index in the environment (expected a Slurm array task, SLURM_ARRAY_TASK_ID, or a "
                  "Kubernetes Indexed Job, JOB_COMPLETION_INDEX with --shard auto/N)");
    s = ShardId{static_cast<int>(*k8s), 0, "JOB_COMPLETION_INDEX=" + std::to_string(*k8s)};
  }
  if (count >= 0) {
    if (s->count != 0 && s->count != count)
      throw Error("--shard " + value + ": the scheduler says " + std::to_string(s->count) + " tasks (" + s->source +
                  "), not " + std::to_string(count));
    s->count = static_cast<int>(count);
    s->source += " of --shard auto/" + std::to_string(count);
  } else if (s->count == 0) {
    throw Error("--shard auto: " + s->source + " gives no task count (expected --shard auto/N)");
  }
  CheckRange(*s, "--shard " + value + " (" + s->source + ")");
  return *s;
}

ShardId ParseShard(const std::string& value) {
  return ParseShard(value, [](const char* name) { return static_cast<const char*>(std::getenv(name)); });
}

}  // namespace prt
