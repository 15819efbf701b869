// prt merge DIR: the last step of a farm job. The shards its tasks wrote into DIR (prt
// precompute --shard I/N, app/precompute_shard.h) are checked and assembled
// (farm/assemble_shards.h), and the precompute they were made by is run once more with that
// transport: what needs every vertex (the course's files, the cache, the transfer matrices and
// their clustered PCA) is written as one run on one machine writes it, byte for byte.
#include <filesystem>
#include <optional>

#include "app/commands.h"
#include "app/precompute_shard.h"
#include "app/render_args.h"
#include "app/reference_shard.h"
#include "app/render_shard.h"
#include "bases/list.h"
#include "core/atomic_file.h"
#include "core/log.h"
#include "core/error.h"
#include "farm/assemble_bounces.h"
#include "farm/assemble_reference.h"
#include "farm/assemble_shards.h"
#include "precompute_io/bounce_shard.h"
#include "precompute_io/reference_shard.h"
#include "precompute_io/transport_shard.h"

namespace prt {
namespace {

namespace fs = std::filesystem;

/// `command` with its --out folder replaced by `dir` (the folder may have been moved since).
std::vector<std::string> WithOut(std::vector<std::string> command, const std::string& dir) {
  for (std::size_t i = 0; i < command.size(); ++i) {
    if (command[i] == "--out" && i + 1 < command.size()) command[i + 1] = dir;
    else if (command[i].rfind("--out=", 0) == 0) command[i] = "--out=" + dir;
  }
  return command;
}

/// The command the shards were made by (its name first, ShardCommand), run with their
/// assembled transport: precompute's files, or render's frames. Returns its exit code.
int RunMerged(std::vector<std::string> command, const ShardedTransport& sharded) {
  const std::string name = command.empty() ? std::string() : command.front();
  if (!command.empty()) command.erase(command.begin());
  if (name == "precompute") return Precompute(command, sharded);
  if (name == "render") return Render(command, sharded);
  throw Error("the shards were made by '" + name + "', which prt merge does not run (expected prt precompute or "
              "prt render's shards)");
}

/// Removes the shard files of `cache_name` in `dir` (defined below).
void RemoveShards(const std::string& dir, const std::string& cache_name);

/// A reference's shards assembled (farm/assemble_reference.h) and its command run once with
/// them: reference.txt and reference.png as one run writes them; the shards then removed.
int MergeReference(const std::string& dir, bool keep, bool quiet) {
  const AssembledReference assembled = AssembleReference(dir);
  Summary("merge: " + std::to_string(assembled.count) + " reference shards in " + dir + ", whole and of one job (" +
          std::to_string(assembled.reference.radiance.size()) + " vertices)");
  std::vector<std::string> command = WithOut(assembled.command, dir);
  if (command.empty() || command.front() != "reference")
    throw Error(dir + ": reference shards made by '" + (command.empty() ? std::string() : command.front()) +
                "' (expected prt reference's)");
  command.erase(command.begin());
  if (quiet) command.push_back("--quiet");
  const int status = ReferenceCommand(command, &assembled);
  if (status == 0 && !keep) {
    RemoveShards(dir, kReferenceShardBase);
    Summary("merge: removed the " + std::to_string(assembled.count) + " shard files (--keep-shards keeps them)");
  }
  return status;
}

/// Removes the shard files of `cache_name` in `dir`, and the temporary files killed tasks left
/// while writing one (all tasks have ended when the merge runs).
void RemoveShards(const std::string& dir, const std::string& cache_name) {
  std::error_code ec;
  std::vector<fs::path> doomed;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
    std::string name = entry.path().filename().string();
    if (AtomicFile::IsTemporaryName(name)) name = name.substr(1, name.rfind(AtomicFile::kTemporaryTag) - 1);
    int index = 0, count = 0;
    if (IsShardFileName(name, cache_name, index, count)) doomed.push_back(entry.path());
  }
  for (const fs::path& path : doomed) fs::remove(path, ec);
}

/// True when `dir` holds a file of a stage of interreflection (a bounce shard or state).
bool HasBounceFiles(const std::string& dir, const std::string& cache_name) {
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name == BounceStateName(cache_name) || name.rfind(cache_name + ".bounce-", 0) == 0 ||
        name.rfind(BounceHitsName(cache_name) + ".", 0) == 0)
      return true;
  }
  return false;
}

/// Removes interreflection's stage files of `cache_name` in `dir`: the shards of stages `from`
/// to `to` (from 0: with the hits the bounces gather at), and the state when asked (with the
/// temporaries of killed tasks).
void RemoveBounceFiles(const std::string& dir, const std::string& cache_name, int from, int to, bool state) {
  for (int stage = from; stage <= to; ++stage) RemoveShards(dir, BounceStageName(cache_name, stage));
  if (from == 0) RemoveShards(dir, BounceHitsName(cache_name));
  std::error_code ec;
  if (state) fs::remove(dir + "/" + BounceStateName(cache_name), ec);
}

/// The next stage of interreflection's bounces merged (farm/assemble_bounces.h): the state
/// updated for the tasks' next stage, or, once the bounces end, the precompute run with their
/// transport and the stage files removed.
int MergeBounces(const std::string& dir, const std::string& cache_name, bool keep, int given, bool quiet) {
  const std::string state_path = dir + "/" + BounceStateName(cache_name);
  const std::optional<BounceState> state = LoadBounceState(state_path);
  // A stage named (prt farm's chain) and merged already, or after the bounces ended: nothing to
  // assemble. The chain's last merge removes the state an early end kept for the stages after it.
  if (given >= 0 && state && (state->done || given <= state->stage)) {
    Summary("merge: nothing to merge: bounce stage " + std::to_string(given) + " is merged already" +
            (state->done ? " (the bounces ended after stage " + std::to_string(state->stage) + ": " + state->stop + ")" : ""));
    if (state->done && given >= state->bounces && !keep) RemoveBounceFiles(dir, cache_name, 0, state->bounces, true);
    return 0;
  }
  if (state && state->done)
    throw Error(state_path + ": the bounces ended after stage " + std::to_string(state->stage) +
                " and their transport is written (expected no merge: remove the state to start again)");
  const int stage = state ? state->stage + 1 : 0;
  if (given >= 0 && given != stage)
    throw Error("--bounce-stage " + std::to_string(given) + ": the folder's bounces are " +
                (state ? "at stage " + std::to_string(state->stage) : std::string("not begun")) + " (expected stage " +
                std::to_string(stage) + ": the stages run in order)");
  const AssembledStage assembled = AssembleStage(dir, cache_name, stage);
  const BounceState merged = MergeStage(state, assembled);
  Summary("merge: bounce stage " + std::to_string(stage) + " (" +
          (stage == 0 ? std::string("the direct pass") : "bounce " + std::to_string(stage)) + ") of " +
          std::to_string(assembled.files.size()) + " shards in " + dir + ", whole and of one job");
  if (!merged.done) {
    WriteBounceState(state_path, merged);
    if (stage > 0 && !keep) RemoveBounceFiles(dir, cache_name, stage, stage, false);
    Summary("merge: bounce " + std::to_string(stage + 1) + " of " + std::to_string(merged.bounces) +
            " next: run the same tasks again, then prt merge " + dir);
    return 0;
  }
  int lmax = 0;
  while ((lmax + 1) * (lmax + 1) < merged.coefficients) ++lmax;
  const Transport transport = BouncedTransport(merged, lmax);
  Summary("merge: bounces: " + merged.stop);
  std::vector<std::string> command = WithOut(merged.command, dir);
  if (quiet) command.push_back("--quiet");
  const int status = RunMerged(command, {&transport, merged.key, merged.shards});
  if (status != 0) return status;
  // The chain goes on past an early end: the state stays, done, for its later stages.
  if (given >= 0 && given < merged.bounces) {
    WriteBounceState(state_path, merged);
    if (!keep) RemoveBounceFiles(dir, cache_name, 0, stage, false);
    return 0;
  }
  if (!keep) {
    RemoveBounceFiles(dir, cache_name, 0, stage, true);
    Summary("merge: removed the bounce stages' shard files and state (--keep-shards keeps them)");
  }
  return 0;
}

}  // namespace

CommandSpec MergeSpec() {
  return {"prt merge DIR",
          "The last step of a farm job: checks the shards that prt precompute --shard I/N --out DIR wrote into DIR "
          "(whole, made by the same command from the same mesh and options, every shard 0..N-1 present once), "
          "assembles them, and writes into DIR what that precompute without --shard writes there: light.txt, "
          "transport.txt, the cache and, for a glossy material, the transfer matrices, byte for byte as one run on "
          "one machine writes them. A missing, damaged or foreign shard is refused with its name and reason before "
          "anything is written. The shard files are removed once the merge has succeeded.\n\n"
          "Interreflection runs in stages (the direct pass, then each bounce): each merge assembles its stage "
          "into DIR/transport.cache.bounces for the tasks' next stage, and the merge of the last writes the "
          "folder.",
          {{"options",
            {{"--keep-shards", "", "keep the shard files after a successful merge", "off: removed"},
             {"--bounce-stage", "K",
              "interreflection: merge stage K of the bounces (0 the direct pass, then each bounce), as prt farm's "
              "chain does; a stage merged already, or after the bounces ended, is success with nothing to do",
              "off: the stage after the last merged"},
             QuietOption()}}}};
}

int RunMerge(const std::vector<std::string>& tokens) {
  Args args("merge", tokens, MergeSpec());
  const bool keep = args.Flag("--keep-shards");
  // -1: no stage named (plain numbers: the compiler cannot follow an optional through here)
  const int given = args.Has("--bounce-stage") ? args.Int("--bounce-stage", 0, 0, 1000) : -1;
  const bool quiet = args.Flag("--quiet");
  SetQuiet(quiet);
  const std::vector<std::string> dirs = args.TakePositionals();
  args.Finish();
  if (dirs.size() != 1) args.Fail("expected one folder, DIR (got " + std::to_string(dirs.size()) + ")");
  const std::string& dir = dirs[0];
  // The basis whose shards are there: its cache's name names them.
  const Basis* basis = DefaultBasis();
  for (const Basis* b : Bases()) {
    std::error_code ec;
    for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
      int index = 0, count = 0;
      if (IsShardFileName(entry.path().filename().string(), b->CacheName(), index, count)) basis = b;
    }
  }
  if (!fs::is_directory(dir)) throw Error(dir + ": no such folder (expected the --out DIR the shards were written to)");
  // A reference's shards: its numbers, not a transport.
  {
    std::error_code ec;
    bool reference = false;
    for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
      int index = 0, count = 0;
      reference |= IsShardFileName(entry.path().filename().string(), kReferenceShardBase, index, count);
    }
    if (reference) return MergeReference(dir, keep, quiet);
  }
  // A transport's shards first: a bounce state left from another job does not take them over.
  bool transport_shards = false;
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
    int index = 0, count = 0;
    transport_shards |= IsShardFileName(entry.path().filename().string(), basis->CacheName(), index, count);
  }
  if (!transport_shards && (given >= 0 || HasBounceFiles(dir, basis->CacheName())))
    return MergeBounces(dir, basis->CacheName(), keep, given, quiet);
  const AssembledShards shards = AssembleShards(dir, basis->CacheName());
  Summary("merge: " + std::to_string(shards.count) + " shards in " + dir + ", whole and of one job (" +
          std::to_string(shards.transport.vertices) + " vertices)");
  ShardedTransport sharded{&shards.transport, shards.key, shards.count};
  std::vector<std::string> command = WithOut(shards.command, dir);
  if (quiet) command.push_back("--quiet");  // the shards' command has none (ShardCommand)
  const int status = RunMerged(command, sharded);
  if (status == 0 && !keep) {
    RemoveShards(dir, basis->CacheName());
    Summary("merge: removed the " + std::to_string(shards.count) + " shard files (--keep-shards keeps them)");
  }
  return status;
}

}  // namespace prt
