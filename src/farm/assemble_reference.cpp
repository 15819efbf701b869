#include "farm/assemble_reference.h"

#include <map>
#include <optional>

#include "core/error.h"
#include "farm/assemble_shards.h"
#include "precompute_io/reference_shard.h"

namespace prt {

AssembledReference AssembleReference(const std::string& dir) {
  const std::map<int, std::string> named = ShardFiles(dir, kReferenceShardBase);
  AssembledReference out;
  out.count = int(named.size());
  ShardSetCheck check(out.count);
  Reference& ref = out.reference;
  for (const auto& [index, path] : named) {
    std::string why;
    std::optional<ReferenceShard> s = ReadReferenceShard(path, why);
    if (!s) throw Error(path + ": " + why + " (expected a whole shard: run task " + std::to_string(index) + " again)");
    check.Add(path, index, {s->index, s->count, s->key, &s->command, s->vertices, s->block}, "mesh, light or options");
    ref.radiance.insert(ref.radiance.end(), s->radiance.begin(), s->radiance.end());
    ref.error.insert(ref.error.end(), s->error.begin(), s->error.end());
    ref.rays += s->rays;
    out.files.push_back(path);
  }
  check.Finish(named.rbegin()->second);
  out.command = check.command();
  out.key = check.key();
  SummarizeReference(ref);
  return out;
}

}  // namespace prt
