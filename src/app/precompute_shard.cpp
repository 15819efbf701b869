#include "app/precompute_shard.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <optional>

#include "app/pipeline.h"
#include "bases/list.h"
#include "core/error.h"
#include "core/log.h"
#include "core/output_folder.h"
#include "core/text.h"
#include "farm/vertex_blocks.h"
#include "precompute/bounce_stages.h"
#include "precompute/transport.h"
#include "precompute/transport_bounce.h"
#include "precompute_io/bounce_shard.h"
#include "precompute_io/transport_cache.h"
#include "precompute_io/transport_shard.h"

namespace prt {

namespace fs = std::filesystem;

std::vector<std::string> ShardCommand(const std::string& name, const std::vector<std::string>& tokens) {
  std::vector<std::string> kept = {name};
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const std::string& t = tokens[i];
    // A path made absolute: the merge may run in another folder, and `./scene.obj` is the task's
    // `scene.obj`. An --env that names no file is a built-in light, kept as it is.
    if ((t == "--mesh" || t == "--env" || t == "--texture" || t == "--cache" || t == "--out") && i + 1 < tokens.size()) {
      std::error_code ec;
      const std::string& value = tokens[i + 1];
      const bool path = t == "--out" || (t == "--cache" && value != "none") || fs::exists(value, ec);
      kept.push_back(t);
      kept.push_back(path ? fs::absolute(value, ec).lexically_normal().string() : value);
      ++i;
      continue;
    }
    if (t == "--shard" || t == "--threads" || t == "--bounce-stage") {
      ++i;  // and its value
      continue;
    }
    if (t == "--quiet" || t.rfind("--shard=", 0) == 0 || t.rfind("--threads=", 0) == 0 ||
        t.rfind("--bounce-stage=", 0) == 0)
      continue;
    kept.push_back(t);
  }
  return kept;
}

std::vector<OptionSpec> ShardOptions(const std::string& file, const std::string& merged) {
  return {{"--shard", "I/N",
           "compute only vertex block I of N (0-based; blocks of whole vertices, balanced by work) and write it as " +
               file + ", for a farm job: prt merge DIR then " + merged +
               ". auto: I and N from a Slurm array task (SLURM_ARRAY_TASK_ID with SLURM_ARRAY_TASK_COUNT, or the "
               "array's MIN and MAX); auto/N: N given, I from SLURM_ARRAY_TASK_ID or a Kubernetes Indexed Job's "
               "JOB_COMPLETION_INDEX. Interreflection runs in stages, the tasks and the merge once for the direct pass "
               "and once for each bounce (docs/CLI.md, \"A farm job\"); not with a glossy material yet",
           "off: every vertex"},
          {"--bounce-stage", "K",
           "with --shard and --transport interreflection: run stage K of the bounces (0 the direct pass, then each "
           "bounce), as prt farm's chain does; a stage merged already is success with nothing to do",
           "off: the stage after the last merged"}};
}

std::optional<ShardTask> ReadShardTask(Args& args, const SceneOptions& options) {
  const auto shard_option = args.String("--shard");
  const std::optional<int> bounce_stage =
      args.Has("--bounce-stage") ? std::optional<int>(args.Int("--bounce-stage", 0, 0, 1000)) : std::nullopt;
  if (bounce_stage && !shard_option) args.Fail("--bounce-stage: only with --shard (a stage of a farm job's bounces)");
  if (!shard_option) return std::nullopt;
  if (!options.basis->Traits().shards)
    args.Fail("--shard: --basis " + options.basis->Name() + "'s transport does not split into vertex blocks yet " +
              "(expected --basis " + DefaultBasis()->Name() + ", or the run on one machine)");
  if (options.transport == "interreflection" && options.material.glossy)
    args.Fail("--shard: not with --transport interreflection and a glossy material yet (the glossy lobe's bounced "
              "light is gathered in one pass after the bounces: run it on one machine)");
  ShardTask task;
  try {
    task.shard = ParseShard(*shard_option);
  } catch (const Error& e) {
    args.Fail(e.what());
  }
  if (bounce_stage && options.transport != "interreflection")
    args.Fail("--bounce-stage: only with --transport interreflection (its stages are the direct pass and each bounce)");
  if (bounce_stage && *bounce_stage > options.bounces)
    args.Fail("--bounce-stage " + std::to_string(*bounce_stage) + ": past the last stage, " +
              std::to_string(options.bounces) + " (expected 0..--bounces)");
  task.stage = bounce_stage;
  return task;
}

int RunBounceStage(const Mesh& mesh, const TransportOptions& topts, const std::string& cache, const ShardId& shard,
                   const std::string& out, const std::vector<std::string>& command, std::optional<int> given) {
  const std::uint64_t key = TransportKey(mesh, topts);
  const std::string state_path = out + "/" + BounceStateName(cache);
  const std::optional<BounceState> state = LoadBounceState(state_path);
  if (state) {
    if (state->key != key || state->command != command || state->shards != shard.count)
      throw Error(state_path + ": the bounces of another job (made by another command, mesh or --shard count) " +
                  "(expected this job's: remove the folder's shards and bounce state to start again)");
  }
  const std::string done = "shard: " + std::to_string(shard.index) + " of " + std::to_string(shard.count) + ": nothing to do, ";
  if (state && state->done) {
    Summary(done + "the bounces ended after stage " + std::to_string(state->stage) + " (" + state->stop + ")");
    return 0;
  }
  // A stage named (prt farm's chain): one already merged is done (the task ran again).
  if (given && state && *given <= state->stage) {
    Summary(done + "stage " + std::to_string(*given) + " is merged already");
    return 0;
  }
  // A stage after the first with no state: the job's last merge has removed it, and written the
  // transport (a task run again after it).
  std::string why;
  if (given && *given > 0 && !state && ReadTransportCache(out + "/" + cache, key, why)) {
    Summary(done + out + "/" + cache + " holds this job's transport already (its last merge has run)");
    return 0;
  }
  if (given && *given != (state ? state->stage + 1 : 0))
    throw Error("--bounce-stage " + std::to_string(*given) + ": the folder's bounces are " +
                (state ? "at stage " + std::to_string(state->stage) : std::string("not begun")) +
                " (expected stage " + std::to_string(state ? state->stage + 1 : 0) + ": the stages run in order)");
  const int stage = state ? state->stage + 1 : 0;
  const BounceScene scene = MakeBounceScene(mesh, topts);
  const std::vector<std::uint64_t> work(scene.mesh.vertex_count(), 1);
  BounceShard s;
  s.index = shard.index;
  s.count = shard.count;
  s.stage = stage;
  s.key = key;
  s.command = command;
  s.block = BlockOf(work, shard.index, shard.count);
  s.vertices = scene.mesh.vertex_count();
  s.channels = scene.channels;
  s.coefficients = scene.count;
  s.bounces = topts.bounces;
  s.tolerance = topts.bounce_tolerance;
  s.own = scene.own;
  const auto t0 = std::chrono::steady_clock::now();
  const std::size_t first = s.block.begin, last = s.block.end;
  if (stage == 0) {
    DirectResult direct = DirectStage(scene, s.block);
    s.rows.assign(direct.transfer.begin() + std::ptrdiff_t(first * scene.count),
                  direct.transfer.begin() + std::ptrdiff_t(last * scene.count));
    VertexBlock own = s.block;
    own.end = std::min<std::size_t>(own.end, scene.own);
    s.front_hits = FrontHits(direct.hits, own);
    // The hits, in a file of their own that no merge reads: only those on the lit side of a
    // surface, as the bounces gather nothing from the others (transport_bounce.h).
    BounceShard hits = s;
    hits.stage = kHitsStage;
    hits.rows.clear();
    hits.hits.resize(last - first);
    for (std::size_t v = first; v < last; ++v) {
      std::vector<VertexHit>& at = direct.hits[v];
      at.erase(std::remove_if(at.begin(), at.end(), [](const VertexHit& h) { return !h.front; }), at.end());
      hits.hits[v - first] = std::move(at);
    }
    WriteBounceShard(out + "/" + ShardFileName(BounceHitsName(cache), shard.index, shard.count), hits);
  } else {
    // This block's hits, from its stage-0 shard.
    const std::string zero = out + "/" + ShardFileName(BounceHitsName(cache), shard.index, shard.count);
    std::string unread;
    std::optional<BounceShard> mine = ReadBounceShard(zero, unread);
    if (!mine) throw Error(zero + ": " + unread + " (expected this task's direct pass, which bounce " + std::to_string(stage) +
                           " gathers at)");
    if (mine->stage != kHitsStage || mine->key != key || mine->block.begin != first || mine->block.end != last)
      throw Error(zero + ": another job's or block's direct pass (expected this task's)");
    std::vector<std::vector<VertexHit>> hits(scene.mesh.vertex_count());
    std::move(mine->hits.begin(), mine->hits.end(), hits.begin() + std::ptrdiff_t(first));
    const std::size_t stride = std::size_t(scene.channels) * scene.count;
    std::vector<double> next(scene.mesh.vertex_count() * stride, 0.0);
    BounceRows(scene.mesh, scene.plan, hits, state->current, scene.channels, scene.count, s.block, next,
               "bounce " + std::to_string(stage));
    s.rows.assign(next.begin() + std::ptrdiff_t(first * stride), next.begin() + std::ptrdiff_t(last * stride));
  }
  const std::string path = out + "/" + ShardFileName(BounceStageName(cache, stage), shard.index, shard.count);
  WriteBounceShard(path, s);
  Summary("shard: " + std::to_string(shard.index) + " of " + std::to_string(shard.count) + " (" + shard.source +
          "): " + (stage == 0 ? std::string("the direct pass") : "bounce " + std::to_string(stage)) + " of vertices " +
          std::to_string(first) + " to " + std::to_string(last - 1) + " of " + std::to_string(s.vertices) +
          (s.vertices != s.own ? " (the mesh's " + std::to_string(s.own) + " and the senders split for the bounces)" : "") +
          Formatted(" [%.3f s]", SecondsSince(t0)) + "; wrote " + path + " (prt merge " + out +
          " assembles the stage once all " + std::to_string(shard.count) + " are written; then this task again)");
  return 0;
}

int RunPrecomputeShard(const SceneOptions& options, const ShardId& shard, const std::string& out,
                       const std::vector<std::string>& command, std::optional<int> stage) {
  CreateFolder(out);
  const std::string path = out + "/" + ShardFileName(options.basis->CacheName(), shard.index, shard.count);
  const Mesh mesh = LoadSceneMesh(options);
  TransportOptions topts = TransportOptionsOf(options);
  topts.matrices = options.material.glossy;  // precompute's glossy transfer: matrices for any view
  if (topts.mode == TransportMode::kInterreflection)
    return RunBounceStage(mesh, topts, options.basis->CacheName(), shard, out, command, stage);
  // Every vertex of a precompute casts the same directions (no camera): blocks of equal work
  // are blocks of equal count.
  const std::vector<std::uint64_t> work(mesh.vertex_count(), 1);
  topts.block = BlockOf(work, shard.index, shard.count);
  Summary("shard: " + std::to_string(shard.index) + " of " + std::to_string(shard.count) + " (" + shard.source +
          "): vertices " + std::to_string(topts.block.begin) + " to " + std::to_string(topts.block.end - 1) + " of " +
          std::to_string(mesh.vertex_count()));

  TransportShard s;
  s.index = shard.index;
  s.count = shard.count;
  s.key = TransportKey(mesh, topts);  // the whole run's: the key leaves the block out
  s.command = command;
  s.block = topts.block;
  const auto t0 = std::chrono::steady_clock::now();
  TransportReport report;
  const Transport whole = ComputeTransport(mesh, topts, &report);
  s.rows = BlockRows(whole, topts.block);
  s.rows.material = topts.material;
  const double seconds = SecondsSince(t0);
  WriteTransportShard(path, s);
  Summary("transport: " + std::string(TransportModeName(topts.mode)) + ", lmax " + std::to_string(topts.lmax) +
          Formatted(" [%.3f s]", seconds) + "; " + std::to_string(report.rays) + " rays; wrote " + path +
          " (prt merge " + out + " assembles the shards once all " + std::to_string(shard.count) + " are written)");
  return 0;
}

}  // namespace prt
