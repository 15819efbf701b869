#include "precompute_io/transport_shard.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string_view>

#include "core/atomic_file.h"
#include "core/hash.h"
#include "sh/coeffs.h"

namespace prt {
namespace {

constexpr char kMagic[8] = {'P', 'R', 'T', 'S', 'H', 'A', 'R', 'D'};
constexpr std::uint32_t kFormatVersion = 1;
constexpr std::uint32_t kHasGlossy = 1, kHasMatrices = 2;

struct Header {
  char magic[8];
  std::uint32_t version, lmax, channels, parts, index, count;
  std::uint64_t vertices, begin, end, key, command_bytes, checksum;
};
static_assert(sizeof(Header) == 80, "shard header layout");

/// FNV-1a of the header (its checksum field 0), the command and the rows: a flipped bit of the
/// key or of a block's bounds is a damaged shard, not another job's.
std::uint64_t Checksum(Header header, const std::string& command, const Transport& t) {
  header.checksum = 0;
  std::uint64_t h = Fnv1a(&header, sizeof header);
  h = Fnv1a(command, h);
  for (const std::vector<float>* part : {&t.coeffs, &t.glossy, &t.matrices})
    h = Fnv1a(part->data(), part->size() * sizeof(float), h);
  return h;
}

}  // namespace

std::string JoinShardCommand(const std::vector<std::string>& words) {
  std::string joined;
  for (std::size_t i = 0; i < words.size(); ++i) joined += (i ? std::string(1, '\0') : std::string()) + words[i];
  return joined;
}

std::vector<std::string> SplitShardCommand(const std::string& joined) {
  std::vector<std::string> words;
  for (std::size_t at = 0; at <= joined.size() && !joined.empty();) {
    const std::size_t end = std::min(joined.find('\0', at), joined.size());
    words.push_back(joined.substr(at, end - at));
    at = end + 1;
  }
  return words;
}

std::string ShardFileName(const std::string& cache_name, int index, int count) {
  char suffix[40];
  std::snprintf(suffix, sizeof suffix, ".shard-%05d-of-%05d", index, count);
  return cache_name + suffix;
}

bool IsShardFileName(const std::string& name, const std::string& cache_name, int& index, int& count) {
  const std::string head = cache_name + ".shard-";
  if (name.size() != head.size() + 14 || name.compare(0, head.size(), head) != 0) return false;
  const std::string tail = name.substr(head.size());  // IIIII-of-NNNNN
  if (tail.compare(5, 4, "-of-") != 0) return false;
  const std::string i = tail.substr(0, 5), n = tail.substr(9);
  if (i.find_first_not_of("0123456789") != std::string::npos || n.find_first_not_of("0123456789") != std::string::npos)
    return false;
  index = std::stoi(i);
  count = std::stoi(n);
  return count >= 1 && index < count;  // a name no shard has: not a shard
}

Transport BlockRows(const Transport& whole, const VertexBlock& block) {
  Transport rows;
  rows.lmax = whole.lmax;
  rows.channels = whole.channels;
  rows.vertices = whole.vertices;
  rows.material = whole.material;
  const std::size_t n = CoeffCount(whole.lmax), stride = std::size_t(whole.channels) * n;
  const auto slice = [&](const std::vector<float>& all, std::size_t per_vertex) {
    if (all.empty()) return std::vector<float>();
    return std::vector<float>(all.begin() + std::ptrdiff_t(block.begin * per_vertex),
                              all.begin() + std::ptrdiff_t(block.end * per_vertex));
  };
  rows.coeffs = slice(whole.coeffs, stride);
  rows.glossy = slice(whole.glossy, stride);
  rows.matrices = slice(whole.matrices, stride * n);
  return rows;
}

void WriteTransportShard(const std::string& path, const TransportShard& s) {
  const std::string command = JoinShardCommand(s.command);
  Header h{};
  std::memcpy(h.magic, kMagic, sizeof kMagic);
  h.version = kFormatVersion;
  h.lmax = static_cast<std::uint32_t>(s.rows.lmax);
  h.channels = static_cast<std::uint32_t>(s.rows.channels);
  h.parts = (s.rows.glossy.empty() ? 0 : kHasGlossy) | (s.rows.matrices.empty() ? 0 : kHasMatrices);
  h.index = static_cast<std::uint32_t>(s.index);
  h.count = static_cast<std::uint32_t>(s.count);
  h.vertices = s.rows.vertices;
  h.begin = s.block.begin;
  h.end = s.block.end;
  h.key = s.key;
  h.command_bytes = command.size();
  h.checksum = Checksum(h, command, s.rows);
  std::vector<std::string_view> parts = {{reinterpret_cast<const char*>(&h), sizeof h}, command};
  for (const std::vector<float>* part : {&s.rows.coeffs, &s.rows.glossy, &s.rows.matrices})
    parts.emplace_back(reinterpret_cast<const char*>(part->data()), part->size() * sizeof(float));
  WriteFileAtomic(path, parts);
}

std::optional<TransportShard> ReadTransportShard(const std::string& path, std::string& why) {
  std::ifstream in(path, std::ios::binary);
  Header h{};
  if (!in) {
    why = "cannot be read";
    return std::nullopt;
  }
  if (!in.read(reinterpret_cast<char*>(&h), sizeof h) || std::memcmp(h.magic, kMagic, sizeof kMagic) != 0) {
    why = "not a prt shard file";
    return std::nullopt;
  }
  if (h.version != kFormatVersion) {
    why = "shard format version " + std::to_string(h.version) + " (expected " + std::to_string(kFormatVersion) + ")";
    return std::nullopt;
  }
  if (h.lmax > 64 || (h.channels != 1 && h.channels != 3) || h.parts > (kHasGlossy | kHasMatrices) ||
      h.vertices > (1ULL << 32) || h.count < 1 || h.index >= h.count || h.begin >= h.end || h.end > h.vertices ||
      h.command_bytes > (1u << 20)) {
    why = "corrupt header";
    return std::nullopt;
  }
  const std::uint64_t n = std::uint64_t(h.lmax + 1) * (h.lmax + 1);
  const std::uint64_t per_part = (h.end - h.begin) * h.channels * n;
  const std::uint64_t matrix_floats = (h.parts & kHasMatrices) ? per_part * n : 0;
  const std::uint64_t floats = per_part * ((h.parts & kHasGlossy) ? 2 : 1) + matrix_floats;
  const std::uint64_t expected = sizeof h + h.command_bytes + floats * sizeof(float);
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec || size != expected) {
    why = "truncated or oversized (" + std::to_string(size) + " bytes, expected " + std::to_string(expected) + ")";
    return std::nullopt;
  }
  std::string command(h.command_bytes, '\0');
  TransportShard s;
  s.rows.lmax = static_cast<int>(h.lmax);
  s.rows.channels = static_cast<int>(h.channels);
  s.rows.vertices = h.vertices;
  s.rows.coeffs.resize(per_part);
  s.rows.glossy.resize((h.parts & kHasGlossy) ? per_part : 0);
  s.rows.matrices.resize(matrix_floats);
  bool ok = static_cast<bool>(in.read(command.data(), std::streamsize(command.size())));
  for (std::vector<float>* part : {&s.rows.coeffs, &s.rows.glossy, &s.rows.matrices})
    ok = ok && in.read(reinterpret_cast<char*>(part->data()), std::streamsize(part->size() * sizeof(float)));
  if (!ok) {
    why = "truncated";
    return std::nullopt;
  }
  if (Checksum(h, command, s.rows) != h.checksum) {
    why = "checksum mismatch (corrupted)";
    return std::nullopt;
  }
  s.index = static_cast<int>(h.index);
  s.count = static_cast<int>(h.count);
  s.key = h.key;
  s.block.begin = h.begin;
  s.block.end = h.end;
  s.command = SplitShardCommand(command);
  return s;
}

}  // namespace prt
