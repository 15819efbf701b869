#include "app/precompute_shard.h"

#include <chrono>

#include "app/pipeline.h"
#include "core/log.h"
#include "core/output_folder.h"
#include "core/text.h"
#include "farm/vertex_blocks.h"
#include "precompute/transport.h"
#include "precompute_io/transport_cache.h"
#include "precompute_io/transport_shard.h"

namespace prt {

std::vector<std::string> ShardCommand(const std::vector<std::string>& tokens) {
  std::vector<std::string> kept;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const std::string& t = tokens[i];
    if (t == "--shard" || t == "--threads") {
      ++i;  // and its value
      continue;
    }
    if (t == "--quiet" || t.rfind("--shard=", 0) == 0 || t.rfind("--threads=", 0) == 0) continue;
    kept.push_back(t);
  }
  return kept;
}

int RunPrecomputeShard(const SceneOptions& options, const ShardId& shard, const std::string& out,
                       const std::vector<std::string>& command) {
  CreateFolder(out);
  const std::string path = out + "/" + ShardFileName(options.basis->CacheName(), shard.index, shard.count);
  const Mesh mesh = LoadSceneMesh(options);
  TransportOptions topts = TransportOptionsOf(options);
  topts.matrices = options.material.glossy;  // precompute's glossy transfer: matrices for any view
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
  s.key = TransportKey(mesh, [&] {
    TransportOptions whole = topts;
    whole.block = VertexBlock{};
    return whole;
  }());
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
