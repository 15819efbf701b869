#include "precompute_io/transport_cache.h"

#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/hash.h"
#include "texture/texture.h"

namespace prt {
namespace {

constexpr char kMagic[8] = {'P', 'R', 'T', 'C', 'A', 'C', 'H', 'E'};
constexpr std::uint32_t kFormatVersion = 2;
constexpr std::uint32_t kHasGlossy = 1, kHasMatrices = 2;

struct Header {
  char magic[8];
  std::uint32_t version, lmax, channels, parts;  ///< parts: kHasGlossy | kHasMatrices
  std::uint64_t vertices, key, checksum;
};
static_assert(sizeof(Header) == 48, "cache header layout");

template <class T>
std::uint64_t HashVector(const std::vector<T>& v, std::uint64_t h) {
  return Fnv1a(v.data(), v.size() * sizeof(T), h);
}

}  // namespace

std::uint64_t TransportKey(const Mesh& mesh, const TransportOptions& o) {
  std::uint64_t h = kFnvOffset;
  h = HashVector(mesh.positions, h);
  h = HashVector(mesh.normals, h);
  h = HashVector(mesh.albedo, h);
  h = HashVector(mesh.triangles, h);
  // A textured mesh's bounces read its texels at the hit points.
  h = HashVector(mesh.corner_uv, h);
  h = HashVector(mesh.triangle_texture, h);
  for (const auto& texture : mesh.textures) {
    const std::uint64_t content = texture->content_hash();
    h = Fnv1a(&content, sizeof content, h);
  }
  // Which vertices the camera sees decides how many directions each one took; without a split
  // every vertex took `samples`, whatever hidden_samples says.
  const bool split = !o.seen.empty() && o.hidden_samples && o.hidden_samples != o.samples;
  if (split) h = HashVector(o.seen, h);
  const std::string options = std::string("prt ") + PRT_VERSION + " mode=" + TransportModeName(o.mode) +
                              " lmax=" + std::to_string(o.lmax) + " samples=" + std::to_string(o.samples) +
                              " hidden_samples=" + std::to_string(split ? o.hidden_samples : o.samples) +
                              " sampler=" + SamplerName(o.sampler) + " bounces=" + std::to_string(o.bounces) +
                              " seed=" + std::to_string(o.seed) + " tol=" + std::to_string(o.bounce_tolerance) +
                              " sets=" + std::to_string(o.direction_sets) +
                              " material=" + (o.matrices ? std::string("any glossy") : o.material.Name()) +
                              " lobe_samples=" + std::to_string(o.lobe_samples) + " matrices=" + std::to_string(o.matrices);
  if (o.material.glossy && !o.matrices) {  // G depends on KS and the eye to the bit; matrices on neither
    h = Fnv1a(&o.material.ks, sizeof o.material.ks, h);
    const glm::dvec3 eye = o.eye.value_or(glm::dvec3(0.0));
    h = Fnv1a(&eye, sizeof eye, h);
  }
  return Fnv1a(options, h);
}

void WriteTransportCache(const std::string& path, const Transport& t, std::uint64_t key) {
  Header h{};
  std::memcpy(h.magic, kMagic, sizeof kMagic);
  h.version = kFormatVersion;
  h.lmax = static_cast<std::uint32_t>(t.lmax);
  h.channels = static_cast<std::uint32_t>(t.channels);
  h.vertices = t.vertices;
  h.key = key;
  h.parts = (t.glossy.empty() ? 0 : kHasGlossy) | (t.matrices.empty() ? 0 : kHasMatrices);
  h.checksum = HashVector(t.matrices, HashVector(t.glossy, HashVector(t.coeffs, kFnvOffset)));
  std::vector<std::string_view> parts = {{reinterpret_cast<const char*>(&h), sizeof h}};
  for (const std::vector<float>* part : {&t.coeffs, &t.glossy, &t.matrices})
    parts.emplace_back(reinterpret_cast<const char*>(part->data()), part->size() * sizeof(float));
  WriteFileAtomic(path, parts);  // in pieces: the matrices are never copied
}

bool StartsLikeTransportCache(const std::string& path) { return FileStartsWith(path, kMagic, sizeof kMagic); }

std::optional<Transport> ReadTransportCache(const std::string& path, std::uint64_t key, std::string& why) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    why = "no cache yet";
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  Header h{};
  if (!in.read(reinterpret_cast<char*>(&h), sizeof h) || std::memcmp(h.magic, kMagic, sizeof kMagic) != 0) {
    why = "not a prt cache file";
    return std::nullopt;
  }
  if (h.version != kFormatVersion) {
    why = "cache format version " + std::to_string(h.version) + " (expected " + std::to_string(kFormatVersion) + ")";
    return std::nullopt;
  }
  if (h.key != key) {
    why = "made from other inputs";
    return std::nullopt;
  }
  if (h.lmax > 64 || (h.channels != 1 && h.channels != 3) || h.parts > (kHasGlossy | kHasMatrices) || h.vertices > (1ULL << 32)) {
    why = "corrupt header";
    return std::nullopt;
  }
  const std::uint64_t n = std::uint64_t(h.lmax + 1) * (h.lmax + 1);
  const std::uint64_t per_part = h.vertices * h.channels * n;
  const std::uint64_t matrix_floats = (h.parts & kHasMatrices) ? per_part * n : 0;
  const std::uint64_t floats = per_part * ((h.parts & kHasGlossy) ? 2 : 1) + matrix_floats;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec || size != sizeof h + floats * sizeof(float)) {
    why = "truncated or oversized (" + std::to_string(size) + " bytes, expected " +
          std::to_string(sizeof h + floats * sizeof(float)) + ")";
    return std::nullopt;
  }
  Transport t;
  t.lmax = static_cast<int>(h.lmax);
  t.channels = static_cast<int>(h.channels);
  t.vertices = h.vertices;
  t.coeffs.resize(per_part);
  t.glossy.resize((h.parts & kHasGlossy) ? per_part : 0);
  t.matrices.resize(matrix_floats);
  for (std::vector<float>* part : {&t.coeffs, &t.glossy, &t.matrices}) {
    if (!in.read(reinterpret_cast<char*>(part->data()), static_cast<std::streamsize>(part->size() * sizeof(float)))) {
      why = "truncated";
      return std::nullopt;
    }
  }
  if (HashVector(t.matrices, HashVector(t.glossy, HashVector(t.coeffs, kFnvOffset))) != h.checksum) {
    why = "checksum mismatch (corrupted)";
    return std::nullopt;
  }
  why = "reused";
  return t;
}

}  // namespace prt
