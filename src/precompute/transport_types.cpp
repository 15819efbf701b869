#include "precompute/transport_types.h"

#include <algorithm>

#include "core/name_table.h"
#include "texture/texture.h"

namespace prt {
namespace {

constexpr auto kModes = MakeNameTable<TransportMode>({
    {TransportMode::kUnshadowed, "unshadowed"},
    {TransportMode::kShadowed, "shadowed"},
    {TransportMode::kInterreflection, "interreflection"},
});
static_assert(kModes.Distinct());

bool GreyAlbedo(const Mesh& mesh) {
  for (const auto& texture : mesh.textures)
    if (!texture->grey()) return false;
  for (const auto& a : mesh.albedo)
    if (a.x != a.y || a.y != a.z) return false;
  return true;
}

}  // namespace

TransportMode TransportModeFromName(const std::string& name) { return kModes.Parse(name, "transport mode"); }

const char* TransportModeName(TransportMode mode) { return kModes.Name(mode); }

std::vector<std::string> TransportModeNames() { return kModes.Names(); }

int LobeSamplesOf(int samples) { return std::max(64, samples / 4); }

int TransportChannels(const Mesh& mesh, TransportMode mode) {
  return mode == TransportMode::kInterreflection && !GreyAlbedo(mesh) ? 3 : 1;
}

}  // namespace prt
