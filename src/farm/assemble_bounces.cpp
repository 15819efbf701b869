#include "farm/assemble_bounces.h"

#include <cstdio>

#include "core/error.h"
#include "farm/assemble_shards.h"
#include "precompute/transport_bounce.h"
#include "precompute_io/transport_shard.h"

namespace prt {

AssembledStage AssembleStage(const std::string& dir, const std::string& cache_name, int stage) {
  const std::string name = BounceStageName(cache_name, stage);
  AssembledStage out;
  std::size_t next = 0;
  for (const auto& [index, path] : ShardFiles(dir, name)) {
    std::string why;
    std::optional<BounceShard> s = ReadBounceShard(path, why);
    if (!s) throw Error(path + ": " + why + " (expected a whole shard: run task " + std::to_string(index) + " again)");
    if (s->index != index || s->stage != stage)
      throw Error(path + ": holds shard " + std::to_string(s->index) + " of stage " + std::to_string(s->stage) +
                  ", not the one its name says (expected the file as prt named it)");
    const BounceShard& f = out.files.empty() ? *s : out.first;
    if (s->command != f.command || s->key != f.key || s->count != f.count || s->vertices != f.vertices ||
        s->channels != f.channels || s->coefficients != f.coefficients || s->own != f.own || s->bounces != f.bounces ||
        s->tolerance != f.tolerance)
      throw Error(path + ": made " + (s->command != f.command ? "by another command" : "from another mesh or options") +
                  " than shard 0 (expected the shards of one job: remove the foreign one and run its task again)");
    if (s->block.begin != next)
      throw Error(path + ": its vertices start at " + std::to_string(s->block.begin) + ", not " + std::to_string(next) +
                  " where the shard before it ends (corrupted)");
    next = s->block.end;
    out.rows.insert(out.rows.end(), s->rows.begin(), s->rows.end());
    out.front_hits += s->front_hits;
    if (out.files.empty()) {
      out.first = std::move(*s);
      out.first.rows.clear();
      out.first.hits.clear();
    }
    out.files.push_back(path);
  }
  if (next != out.first.vertices)
    throw Error(out.files.back() + ": its vertices end at " + std::to_string(next) + ", not at the bounce mesh's " +
                std::to_string(out.first.vertices) + " (corrupted)");
  return out;
}

BounceState MergeStage(const std::optional<BounceState>& before, const AssembledStage& a) {
  const BounceShard& f = a.first;
  const int count = f.coefficients;
  if (f.stage != (before ? before->stage + 1 : 0) || (before && before->done))
    throw Error("bounce stage " + std::to_string(f.stage) + ": not the next one (expected stage " +
                std::to_string(before ? before->stage + 1 : 0) + (before && before->done ? ", and none: the bounces ended" : "") +
                ")");
  if (before && (before->key != f.key || before->command != f.command || before->shards != f.count))
    throw Error("bounce stage " + std::to_string(f.stage) +
                ": its shards were made by another job than the stages before (expected the same command and --shard count)");
  BounceState s;
  if (!before) {
    // Bounce 0: the direct transfer of every vertex, the same for every channel (AddBounces).
    s.key = f.key;
    s.command = f.command;
    s.shards = f.count;
    s.bounces = f.bounces;
    s.channels = f.channels;
    s.coefficients = count;
    s.vertices = f.vertices;
    s.own = f.own;
    s.current = BounceZero(a.rows, f.vertices, f.channels, count);
    s.transfer = s.current;
    s.direct_energy = BounceEnergy(s.current, count);
    s.stage = 0;
    if (a.front_hits == 0) {
      s.done = true;
      s.stop = "no bounce pass: no vertex sees any lit surface of the mesh";
    } else if (f.bounces == 0) {
      s.done = true;
      s.stop = "all 0 bounces computed";
    }
    return s;
  }
  s = *before;
  s.stage = f.stage;
  for (std::size_t i = 0; i < a.rows.size(); ++i) s.transfer[i] += a.rows[i];
  const double share = s.direct_energy > 0.0 ? BounceEnergy(a.rows, count) / s.direct_energy : 0.0;
  if (share < f.tolerance && f.stage < f.bounces) {
    char why[160];
    std::snprintf(why, sizeof why, "stopped after bounce %d of %d: it added %.2g of the direct energy (< %.2g)", f.stage,
                  f.bounces, share, f.tolerance);
    s.done = true;
    s.stop = why;
  } else if (f.stage >= f.bounces) {
    s.done = true;
    s.stop = "all " + std::to_string(f.bounces) + " bounces computed";
  }
  s.current = a.rows;
  return s;
}

Transport BouncedTransport(const BounceState& state, int lmax) {
  Transport t;
  t.lmax = lmax;
  t.channels = state.channels;
  t.vertices = state.own;
  const std::size_t stride = std::size_t(state.channels) * std::size_t(state.coefficients);
  t.coeffs.assign(state.transfer.begin(), state.transfer.begin() + std::ptrdiff_t(state.own * stride));
  return t;
}

}  // namespace prt
