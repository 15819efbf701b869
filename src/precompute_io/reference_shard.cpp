#include "precompute_io/reference_shard.h"

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string_view>

#include "core/atomic_file.h"
#include "core/hash.h"
#include "precompute_io/transport_shard.h"

namespace prt {
namespace {

constexpr char kMagic[8] = {'P', 'R', 'T', 'R', 'E', 'F', 'S', 'H'};
constexpr std::uint32_t kFormatVersion = 1;

struct Header {
  char magic[8];
  std::uint32_t version, index, count, reserved;
  std::uint64_t vertices, begin, end, key, rays, command_bytes, checksum;
};
static_assert(sizeof(Header) == 80, "reference shard header layout");
static_assert(sizeof(glm::dvec3) == 3 * sizeof(double), "dvec3 holds three doubles");

std::uint64_t Checksum(Header header, const std::string& command, const ReferenceShard& s) {
  header.checksum = 0;
  std::uint64_t h = Fnv1a(&header, sizeof header);
  h = Fnv1a(command, h);
  h = Fnv1a(s.radiance.data(), s.radiance.size() * sizeof(glm::dvec3), h);
  return Fnv1a(s.error.data(), s.error.size() * sizeof(glm::dvec3), h);
}

}  // namespace

void WriteReferenceShard(const std::string& path, const ReferenceShard& s) {
  const std::string command = JoinShardCommand(s.command);
  Header h{};
  std::memcpy(h.magic, kMagic, sizeof kMagic);
  h.version = kFormatVersion;
  h.index = static_cast<std::uint32_t>(s.index);
  h.count = static_cast<std::uint32_t>(s.count);
  h.vertices = s.vertices;
  h.begin = s.block.begin;
  h.end = s.block.end;
  h.key = s.key;
  h.rays = s.rays;
  h.command_bytes = command.size();
  h.checksum = Checksum(h, command, s);
  WriteFileAtomic(path, {{reinterpret_cast<const char*>(&h), sizeof h},
                         command,
                         {reinterpret_cast<const char*>(s.radiance.data()), s.radiance.size() * sizeof(glm::dvec3)},
                         {reinterpret_cast<const char*>(s.error.data()), s.error.size() * sizeof(glm::dvec3)}});
}

std::optional<ReferenceShard> ReadReferenceShard(const std::string& path, std::string& why) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    why = "cannot be read";
    return std::nullopt;
  }
  Header h{};
  if (!in.read(reinterpret_cast<char*>(&h), sizeof h) || std::memcmp(h.magic, kMagic, sizeof kMagic) != 0) {
    why = "not a prt reference shard file";
    return std::nullopt;
  }
  if (h.version != kFormatVersion) {
    why = "reference shard format version " + std::to_string(h.version) + " (expected " +
          std::to_string(kFormatVersion) + ")";
    return std::nullopt;
  }
  if (h.vertices > (1ULL << 32) || h.count < 1 || h.index >= h.count || h.begin >= h.end || h.end > h.vertices ||
      h.command_bytes > (1u << 20)) {
    why = "corrupt header";
    return std::nullopt;
  }
  const std::uint64_t rows = h.end - h.begin;
  const std::uint64_t expected = sizeof h + h.command_bytes + 2 * rows * sizeof(glm::dvec3);
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec || size != expected) {
    why = "truncated or oversized (" + std::to_string(size) + " bytes, expected " + std::to_string(expected) + ")";
    return std::nullopt;
  }
  ReferenceShard s;
  std::string command(h.command_bytes, '\0');
  s.radiance.resize(rows);
  s.error.resize(rows);
  const bool ok = in.read(command.data(), std::streamsize(command.size())) &&
                  in.read(reinterpret_cast<char*>(s.radiance.data()), std::streamsize(rows * sizeof(glm::dvec3))) &&
                  in.read(reinterpret_cast<char*>(s.error.data()), std::streamsize(rows * sizeof(glm::dvec3)));
  if (!ok) {
    why = "truncated";
    return std::nullopt;
  }
  if (Checksum(h, command, s) != h.checksum) {
    why = "checksum mismatch (corrupted)";
    return std::nullopt;
  }
  s.index = static_cast<int>(h.index);
  s.count = static_cast<int>(h.count);
  s.key = h.key;
  s.block.begin = h.begin;
  s.block.end = h.end;
  s.vertices = h.vertices;
  s.rays = h.rays;
  s.command = SplitShardCommand(command);
  return s;
}

}  // namespace prt
