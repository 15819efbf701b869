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
  std::size_t next = 0, vertices = 0;
  Reference& ref = out.reference;
  for (const auto& [index, path] : named) {
    std::string why;
    std::optional<ReferenceShard> s = ReadReferenceShard(path, why);
    if (!s) throw Error(path + ": " + why + " (expected a whole shard: run task " + std::to_string(index) + " again)");
    if (s->index != index || s->count != out.count)
      throw Error(path + ": holds shard " + std::to_string(s->index) + " of " + std::to_string(s->count) +
                  ", not the one its name says (expected the file as prt named it)");
    if (index == 0) {
      out.command = s->command;
      out.key = s->key;
      vertices = s->vertices;
    } else if (s->command != out.command || s->key != out.key || s->vertices != vertices) {
      throw Error(path + ": made " + (s->command != out.command ? "by another command" : "from another mesh, light or options") +
                  " than shard 0 (expected the shards of one job: remove the foreign one and run its task again)");
    }
    if (s->block.begin != next)
      throw Error(path + ": its vertices start at " + std::to_string(s->block.begin) + ", not " + std::to_string(next) +
                  " where the shard before it ends (corrupted)");
    next = s->block.end;
    ref.radiance.insert(ref.radiance.end(), s->radiance.begin(), s->radiance.end());
    ref.error.insert(ref.error.end(), s->error.begin(), s->error.end());
    ref.rays += s->rays;
    out.files.push_back(path);
  }
  if (next != vertices)
    throw Error(named.rbegin()->second + ": its vertices end at " + std::to_string(next) + ", not at the mesh's " +
                std::to_string(vertices) + " (corrupted)");
  SummarizeReference(ref);
  return out;
}

}  // namespace prt
