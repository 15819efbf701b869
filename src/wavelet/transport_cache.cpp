#include "wavelet/transport_cache.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string_view>
#include <vector>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/hash.h"
#include "precompute_io/transport_cache.h"

namespace prt {
namespace {

constexpr char kMagic[8] = {'P', 'R', 'T', 'W', 'A', 'V', 'E', 'L'};
constexpr std::uint32_t kFormatVersion = 1;
/// The largest band a header may name (the SH cache's limit).
constexpr int kMaxCachedLmax = 64;

struct Header {
  char magic[8];
  std::uint32_t version, face_size;
  std::int32_t base_lmax, bounce_lmax;
  std::uint32_t bounce_channels, probes;
  std::uint64_t vertices, details, bounce_vertices, key, checksum;
  double kept_energy, seconds;
  std::uint64_t rays;
};
static_assert(sizeof(Header) == 96, "wavelet cache header layout");

/// Coefficients a vertex has in bands 0..lmax (none below 0).
std::uint64_t Bands(int lmax) { return lmax < 0 ? 0 : std::uint64_t(lmax + 1) * std::uint64_t(lmax + 1); }

/// Calls `f` on each array of the payload, in file order (`t` const to write, not to read).
template <class W, class F>
void ForEachArray(W& t, F&& f) {
  f(t.base), f(t.means), f(t.scale), f(t.offsets), f(t.index), f(t.value), f(t.bounce.coeffs), f(t.probes),
      f(t.probe_coeffs);
}

/// The element count each array must have for the counts in `h`, in file order.
std::vector<std::uint64_t> ExpectedCounts(const Header& h) {
  const std::uint64_t v = h.vertices, texels = 6ULL * h.face_size * h.face_size;
  return {v * Bands(h.base_lmax), 6 * v, v, v + 1, h.details, h.details,
          h.bounce_vertices * h.bounce_channels * Bands(h.bounce_lmax), h.probes, h.probes * texels};
}

/// FNV-1a of the header with its checksum field 0, then of every array.
std::uint64_t Checksum(Header h, const WaveletTransport& t) {
  h.checksum = 0;
  std::uint64_t sum = Fnv1a(&h, sizeof h);
  ForEachArray(t, [&sum](const auto& v) { sum = Fnv1a(v.data(), v.size() * sizeof v[0], sum); });
  return sum;
}

Header HeaderOf(const WaveletTransport& t, std::uint64_t key) {
  Header h{};
  std::memcpy(h.magic, kMagic, sizeof kMagic);
  h.version = kFormatVersion;
  h.face_size = static_cast<std::uint32_t>(t.face_size);
  h.base_lmax = t.base_lmax;
  h.bounce_lmax = t.bounce.lmax;
  h.bounce_channels = static_cast<std::uint32_t>(t.bounce.channels);
  h.probes = static_cast<std::uint32_t>(t.probes.size());
  h.vertices = t.vertices;
  h.details = t.index.size();
  h.bounce_vertices = t.bounce.vertices;
  h.key = key;
  h.kept_energy = t.kept_energy;
  h.seconds = t.seconds;
  h.rays = t.rays;
  return h;
}

/// The reason the header's counts cannot be a transport's, or "" when they can.
std::string HeaderProblem(const Header& h) {
  const bool bounce_ok = (h.bounce_channels == 1 || h.bounce_channels == 3) && h.bounce_lmax >= 0 &&
                         h.bounce_lmax <= kMaxCachedLmax && (h.bounce_vertices == 0 || h.bounce_vertices == h.vertices);
  if (h.face_size < 2 || h.face_size > kMaxWaveletFace || h.base_lmax < -1 || h.base_lmax > kMaxCachedLmax ||
      !bounce_ok || h.vertices > (1ULL << 32) || h.details > h.vertices * 6ULL * h.face_size * h.face_size ||
      h.probes > h.vertices)
    return "corrupt header";
  return "";
}

/// The reason the arrays (their checksum matching) cannot be read as a transport, or "": each
/// vertex's details in range, its indices increasing and below the texel count 6 F^2 (an index
/// of 6 F^2 or more would read past the end of a frame's light, wavelet/shade.h), the probes
/// real vertices.
std::string PayloadProblem(const WaveletTransport& t) {
  const std::size_t texels = std::size_t(6) * t.face_size * t.face_size;
  if (t.offsets.front() != 0 || t.offsets.back() != t.index.size()) return "corrupt offsets";
  for (std::size_t v = 0; v < t.vertices; ++v) {
    if (t.offsets[v + 1] < t.offsets[v]) return "corrupt offsets";
    for (std::uint64_t j = t.offsets[v]; j < t.offsets[v + 1]; ++j)
      if (t.index[j] >= texels || (j > t.offsets[v] && t.index[j] <= t.index[j - 1]))
        return "corrupt indices (vertex " + std::to_string(v) + " has detail index " + std::to_string(t.index[j]) +
               ", expected increasing indices below the cube's " + std::to_string(texels) + " texels)";
  }
  for (std::uint32_t p : t.probes)
    if (p >= t.vertices) return "corrupt probes";
  return "";
}

}  // namespace

std::uint64_t WaveletTransportKey(const Mesh& mesh, const TransportOptions& sh, const WaveletOptions& w) {
  // All that the SH transport's key covers: the bounces are that transport, and the direct part
  // reads the same mesh, mode and seed.
  std::uint64_t h = TransportKey(mesh, sh);
  // A hidden vertex takes one ray a texel whatever --hidden-samples says (the SH key covers
  // `seen` only where the two sample counts differ).
  if (std::find(sh.seen.begin(), sh.seen.end(), std::uint8_t{0}) != sh.seen.end())
    h = Fnv1a(sh.seen.data(), sh.seen.size(), Fnv1a(std::string("seen"), h));
  const std::string options = "wavelet cache format=" + std::to_string(kFormatVersion) +
                              " face_size=" + std::to_string(w.face_size) + " budget=" + std::to_string(w.budget) +
                              " split=" + std::to_string(w.split) + " selection=" + SelectionName(w.selection) +
                              " base_lmax=" + std::to_string(w.base_lmax);
  return Fnv1a(options, h);
}

void WriteWaveletCache(const std::string& path, const WaveletTransport& transport, std::uint64_t key) {
  Header h = HeaderOf(transport, key);
  // A transport whose arrays disagree with its counts would be read back as another one.
  const std::vector<std::uint64_t> counts = ExpectedCounts(h);
  bool consistent = transport.bounce.glossy.empty() && transport.bounce.matrices.empty() && HeaderProblem(h).empty();
  std::size_t i = 0;
  ForEachArray(transport, [&](const auto& v) { consistent = consistent && v.size() == counts[i++]; });
  if (!consistent || !PayloadProblem(transport).empty())
    throw Error(path + ": the wavelet transport's arrays disagree with its counts (internal)");
  h.checksum = Checksum(h, transport);
  std::vector<std::string_view> bytes = {{reinterpret_cast<const char*>(&h), sizeof h}};
  ForEachArray(transport, [&bytes](const auto& v) {
    bytes.emplace_back(reinterpret_cast<const char*>(v.data()), v.size() * sizeof v[0]);
  });
  WriteFileAtomic(path, bytes);  // in pieces: the arrays are never copied
}

bool StartsLikeWaveletCache(const std::string& path) { return FileStartsWith(path, kMagic, sizeof kMagic); }

std::optional<WaveletTransport> ReadWaveletCache(const std::string& path, std::uint64_t key, std::string& why) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    why = "no cache yet";
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  Header h{};
  in.read(reinterpret_cast<char*>(&h), sizeof h);
  const std::streamsize got = in.gcount();
  if (got < std::streamsize(sizeof kMagic) || std::memcmp(h.magic, kMagic, sizeof kMagic) != 0) {
    why = StartsLikeTransportCache(path) ? "an SH transport cache (--basis sh), not a wavelet one"
                                         : "not a prt cache file";
    return std::nullopt;
  }
  if (got < std::streamsize(sizeof h)) {
    why = "truncated (" + std::to_string(got) + " bytes, less than its header)";
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
  if (const std::string problem = HeaderProblem(h); !problem.empty()) {
    why = problem;
    return std::nullopt;
  }
  // The size first: a damaged count must not make the reader allocate what the file cannot hold.
  const std::vector<std::uint64_t> counts = ExpectedCounts(h);
  WaveletTransport t;
  std::uint64_t expected = sizeof h;
  std::size_t i = 0;
  ForEachArray(t, [&](const auto& v) { expected += counts[i++] * sizeof v[0]; });
  const auto size = std::filesystem::file_size(path, ec);
  if (ec || size != expected) {
    why = "truncated or oversized (" + std::to_string(size) + " bytes, expected " + std::to_string(expected) + ")";
    return std::nullopt;
  }
  t.face_size = static_cast<int>(h.face_size);
  t.vertices = h.vertices;
  t.base_lmax = h.base_lmax;
  t.bounce.lmax = h.bounce_lmax;
  t.bounce.channels = static_cast<int>(h.bounce_channels);
  t.bounce.vertices = h.bounce_vertices;
  t.kept_energy = h.kept_energy;
  t.seconds = h.seconds;
  t.rays = h.rays;
  bool complete = true;
  i = 0;
  ForEachArray(t, [&](auto& v) {
    v.resize(counts[i++]);
    const auto bytes = static_cast<std::streamsize>(v.size() * sizeof v[0]);
    complete = complete && bool(in.read(reinterpret_cast<char*>(v.data()), bytes));
  });
  if (!complete) {
    why = "truncated";
    return std::nullopt;
  }
  if (Checksum(h, t) != h.checksum) {
    why = "checksum mismatch (corrupted)";
    return std::nullopt;
  }
  if (const std::string problem = PayloadProblem(t); !problem.empty()) {
    why = problem;
    return std::nullopt;
  }
  why = "reused";
  return t;
}

}  // namespace prt
