#include "app/reference_shard.h"

#include "core/hash.h"
#include "core/text.h"
#include "env/environment_hash.h"
#include "precompute_io/transport_cache.h"

namespace prt {

std::uint64_t ReferenceKey(const Mesh& mesh, const Environment& env, const ReferenceOptions& o) {
  // The mesh as the transport cache hashes it (positions, normals, albedo, triangles, textures).
  std::uint64_t h = TransportKey(mesh, TransportOptions{});
  const std::uint64_t light = EnvironmentHash(env);
  h = Fnv1a(&light, sizeof light, h);
  std::string options = std::string("reference mode=") + TransportModeName(o.mode) + " samples=" +
                        std::to_string(o.samples) + " bounces=" + std::to_string(o.bounces) + " seed=" +
                        std::to_string(o.seed) + " table=" + std::to_string(o.table_rows) + "x" +
                        std::to_string(o.table_cols) + " material=" + o.material.Name() +
                        " sampling=" + std::to_string(int(o.glossy_sampling));
  if (o.eye) options += Formatted(" eye=%a,%a,%a", o.eye->x, o.eye->y, o.eye->z);  // to the bit
  return Fnv1a(options, h);
}

}  // namespace prt
