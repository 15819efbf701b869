#include "app/render_shard.h"

#include "app/pipeline.h"
#include "app/precompute_shard.h"
#include "basis/basis.h"
#include "basis/cache_plan.h"
#include "core/log.h"
#include "core/output_folder.h"
#include "farm/vertex_blocks.h"
#include "precompute_io/transport_shard.h"

namespace prt {

std::vector<std::uint64_t> RenderVertexWork(const TransportOptions& topts, std::size_t vertices) {
  if (topts.mode == TransportMode::kUnshadowed) return std::vector<std::uint64_t>(vertices, 1);
  const std::uint64_t seen = std::uint64_t(topts.samples);
  const std::uint64_t hidden = topts.hidden_samples > 0 ? std::uint64_t(topts.hidden_samples) : seen;
  std::vector<std::uint64_t> work(vertices, seen);
  if (!topts.seen.empty())
    for (std::size_t v = 0; v < vertices; ++v) work[v] = topts.seen[v] ? seen : hidden;
  return work;
}

int RunRenderShard(const SceneOptions& scene, const RenderJobOptions& job, const ShardId& shard,
                   const std::vector<std::string>& command, std::optional<int> stage) {
  CreateFolder(job.out);
  const RenderInputs in = LoadRenderInputs(scene, job, nullptr);
  const std::string cache_name = scene.basis->CacheName();
  if (in.transport_options.mode == TransportMode::kInterreflection)
    return RunBounceStage(in.mesh, in.transport_options, cache_name, shard, job.out, command, stage);
  const VertexBlock block =
      BlockOf(RenderVertexWork(in.transport_options, in.mesh.vertex_count()), shard.index, shard.count);
  Summary("shard: " + std::to_string(shard.index) + " of " + std::to_string(shard.count) + " (" + shard.source +
          "): vertices " + std::to_string(block.begin) + " to " + std::to_string(block.end - 1) + " of " +
          std::to_string(in.mesh.vertex_count()) + ", balanced by the directions each casts");
  const CachePlan no_cache;  // a task reads and writes no cache: the merge writes it
  const BasisInputs inputs{in.mesh,    in.transport_options, scene.samples_from_rule, scene.lmax_why, scene.own(),
                           job.draw.axis, job.cpca,         *in.env,                 &in.camera,     no_cache,
                           in.matrices};
  TransportShard s;
  s.index = shard.index;
  s.count = shard.count;
  s.command = command;
  s.block = block;
  const Transport whole = scene.basis->ComputeBlock(inputs, block, s.key);
  s.rows = BlockRows(whole, block);
  s.rows.material = in.transport_options.material;
  const std::string path = job.out + "/" + ShardFileName(cache_name, shard.index, shard.count);
  WriteTransportShard(path, s);
  Summary("shard: wrote " + path + " (prt merge " + job.out + " assembles the shards and renders once all " +
          std::to_string(shard.count) + " are written)");
  return 0;
}

}  // namespace prt
