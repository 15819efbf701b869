#include "precompute_io/bounce_shard.h"

#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string_view>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/hash.h"

namespace prt {
namespace {

constexpr char kShardMagic[8] = {'P', 'R', 'T', 'B', 'N', 'C', 'E', '1'};
constexpr char kStateMagic[8] = {'P', 'R', 'T', 'B', 'S', 'T', 'A', '1'};

/// A payload built field by field (little-endian, as the machine's: every prt host is x86-64).
class Writer {
 public:
  template <class T>
  void Put(const T& value) {
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof value);
  }
  void Put(const std::string& s) {
    Put(std::uint64_t(s.size()));
    bytes_ += s;
  }
  template <class T>
  void PutVector(const std::vector<T>& v) {
    Put(std::uint64_t(v.size()));
    if (!v.empty()) bytes_.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
  void PutWords(const std::vector<std::string>& words) {
    Put(std::uint64_t(words.size()));
    for (const std::string& w : words) Put(w);
  }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

/// Reads a payload back; throws std::out_of_range past its end.
class Reader {
 public:
  explicit Reader(std::string_view bytes) : bytes_(bytes) {}
  template <class T>
  T Get() {
    T value;
    std::memcpy(&value, Take(sizeof value), sizeof value);
    return value;
  }
  std::string GetString() {
    const std::uint64_t n = Get<std::uint64_t>();
    return std::string(Take(n), n);
  }
  template <class T>
  std::vector<T> GetVector() {
    const std::uint64_t n = Get<std::uint64_t>();
    if (n > bytes_.size() / sizeof(T) + 1) throw std::out_of_range("length");
    std::vector<T> v(n);
    const char* from = Take(n * sizeof(T));
    if (n > 0) std::memcpy(v.data(), from, n * sizeof(T));  // an empty vector's data() may be null
    return v;
  }
  std::vector<std::string> GetWords() {
    const std::uint64_t n = Get<std::uint64_t>();
    if (n > bytes_.size()) throw std::out_of_range("length");
    std::vector<std::string> words;
    for (std::uint64_t i = 0; i < n; ++i) words.push_back(GetString());
    return words;
  }
  bool AtEnd() const { return at_ == bytes_.size(); }

 private:
  const char* Take(std::uint64_t n) {
    if (n > bytes_.size() - at_) throw std::out_of_range("truncated");
    const char* p = bytes_.data() + at_;
    at_ += n;
    return p;
  }
  std::string_view bytes_;
  std::size_t at_ = 0;
};

/// The files' checksum: FNV-1a's step over 8-byte words (then the last bytes one at a time),
/// eight times fewer steps than over bytes: a stage-0 shard of mary holds 160 MB of hits.
std::uint64_t Checksum(std::string_view bytes) {
  constexpr std::uint64_t kPrime = 0x100000001b3ULL;
  std::uint64_t h = kFnvOffset;
  std::size_t i = 0;
  for (; i + 8 <= bytes.size(); i += 8) {
    std::uint64_t word;
    std::memcpy(&word, bytes.data() + i, 8);
    h = (h ^ word) * kPrime;
  }
  for (; i < bytes.size(); ++i) h = (h ^ static_cast<unsigned char>(bytes[i])) * kPrime;
  return h;
}

void WriteChecked(const std::string& path, const char (&magic)[8], const std::string& payload) {
  const std::uint64_t checksum = Checksum(payload);
  WriteFileAtomic(path, std::vector<std::string_view>{std::string_view(magic, 8),
                                                      std::string_view(reinterpret_cast<const char*>(&checksum), 8),
                                                      payload});
}

/// The payload of the file at `path` when it starts with `magic` and its checksum holds.
std::optional<std::string> ReadChecked(const std::string& path, const char (&magic)[8], const char* what,
                                       std::string& why) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    why = "cannot be read";
    return std::nullopt;
  }
  const std::string all((std::istreambuf_iterator<char>(in)), {});
  if (all.size() < 16 || std::memcmp(all.data(), magic, 8) != 0) {
    why = all.size() < 8 ? "truncated" : std::string("not a prt ") + what;
    return std::nullopt;
  }
  std::uint64_t checksum = 0;
  std::memcpy(&checksum, all.data() + 8, 8);
  std::string payload = all.substr(16);
  if (Checksum(payload) != checksum) {
    why = "checksum mismatch (truncated or corrupted)";
    return std::nullopt;
  }
  return payload;
}

#pragma pack(push, 1)
struct PackedHit {
  std::uint32_t triangle;
  float u, v;
  std::uint32_t dir;
  std::uint8_t front;
};
#pragma pack(pop)

}  // namespace

std::string BounceStageName(const std::string& cache_name, int stage) {
  return cache_name + ".bounce-" + std::to_string(stage);
}

std::string BounceStateName(const std::string& cache_name) { return cache_name + ".bounces"; }

std::string BounceHitsName(const std::string& cache_name) { return cache_name + ".hits"; }

void WriteBounceShard(const std::string& path, const BounceShard& s) {
  Writer w;
  w.Put(std::int32_t(s.index));
  w.Put(std::int32_t(s.count));
  w.Put(std::int32_t(s.stage));
  w.Put(s.key);
  w.PutWords(s.command);
  w.Put(std::uint64_t(s.block.begin));
  w.Put(std::uint64_t(s.block.end));
  w.Put(s.vertices);
  w.Put(std::int32_t(s.channels));
  w.Put(std::int32_t(s.coefficients));
  w.Put(std::int32_t(s.bounces));
  w.Put(s.tolerance);
  w.Put(s.own);
  w.Put(s.front_hits);
  w.PutVector(s.rows);
  w.Put(std::uint64_t(s.hits.size()));
  for (const auto& hits : s.hits) {
    std::vector<PackedHit> packed;
    packed.reserve(hits.size());
    for (const VertexHit& h : hits) packed.push_back({h.triangle, h.u, h.v, h.dir, std::uint8_t(h.front)});
    w.PutVector(packed);
  }
  WriteChecked(path, kShardMagic, w.bytes());
}

std::optional<BounceShard> ReadBounceShard(const std::string& path, std::string& why) {
  const std::optional<std::string> payload = ReadChecked(path, kShardMagic, "bounce shard", why);
  if (!payload) return std::nullopt;
  try {
    Reader r(*payload);
    BounceShard s;
    s.index = r.Get<std::int32_t>();
    s.count = r.Get<std::int32_t>();
    s.stage = r.Get<std::int32_t>();
    s.key = r.Get<std::uint64_t>();
    s.command = r.GetWords();
    s.block.begin = r.Get<std::uint64_t>();
    s.block.end = r.Get<std::uint64_t>();
    s.vertices = r.Get<std::uint64_t>();
    s.channels = r.Get<std::int32_t>();
    s.coefficients = r.Get<std::int32_t>();
    s.bounces = r.Get<std::int32_t>();
    s.tolerance = r.Get<double>();
    s.own = r.Get<std::uint64_t>();
    s.front_hits = r.Get<std::uint64_t>();
    s.rows = r.GetVector<double>();
    const std::uint64_t with_hits = r.Get<std::uint64_t>();
    if (with_hits != 0 && with_hits != s.block.end - s.block.begin) throw std::out_of_range("hits");
    for (std::uint64_t i = 0; i < with_hits; ++i) {
      std::vector<VertexHit> hits;
      for (const PackedHit& p : r.GetVector<PackedHit>()) hits.push_back({p.triangle, p.u, p.v, p.dir, p.front != 0});
      s.hits.push_back(std::move(hits));
    }
    if (!r.AtEnd() || s.count < 1 || s.index < 0 || s.index >= s.count || s.block.begin >= s.block.end ||
        s.block.end > s.vertices || (s.channels != 1 && s.channels != 3) ||
        s.own > s.vertices || s.coefficients < 1 ||
        s.stage < kHitsStage ||
        s.rows.size() != (s.stage == kHitsStage ? 0 : (s.block.end - s.block.begin) *
                                                          std::uint64_t(s.stage == 0 ? 1 : s.channels) *
                                                          std::uint64_t(s.coefficients)))
      throw std::out_of_range("layout");
    return s;
  } catch (const std::out_of_range&) {
    why = "corrupt layout";
    return std::nullopt;
  }
}

std::optional<BounceState> LoadBounceState(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return std::nullopt;
  std::string why;
  std::optional<BounceState> state = ReadBounceState(path, why);
  if (!state) throw Error(path + ": " + why + " (expected the bounce state the last prt merge wrote)");
  return state;
}

void WriteBounceState(const std::string& path, const BounceState& s) {
  Writer w;
  w.Put(s.key);
  w.PutWords(s.command);
  w.Put(std::int32_t(s.shards));
  w.Put(std::int32_t(s.bounces));
  w.Put(std::int32_t(s.stage));
  w.Put(std::uint8_t(s.done));
  w.Put(s.stop);
  w.Put(std::int32_t(s.channels));
  w.Put(std::int32_t(s.coefficients));
  w.Put(s.vertices);
  w.Put(s.own);
  w.Put(s.direct_energy);
  w.PutVector(s.current);
  w.PutVector(s.transfer);
  WriteChecked(path, kStateMagic, w.bytes());
}

std::optional<BounceState> ReadBounceState(const std::string& path, std::string& why) {
  const std::optional<std::string> payload = ReadChecked(path, kStateMagic, "bounce state", why);
  if (!payload) return std::nullopt;
  try {
    Reader r(*payload);
    BounceState s;
    s.key = r.Get<std::uint64_t>();
    s.command = r.GetWords();
    s.shards = r.Get<std::int32_t>();
    s.bounces = r.Get<std::int32_t>();
    s.stage = r.Get<std::int32_t>();
    s.done = r.Get<std::uint8_t>() != 0;
    s.stop = r.GetString();
    s.channels = r.Get<std::int32_t>();
    s.coefficients = r.Get<std::int32_t>();
    s.vertices = r.Get<std::uint64_t>();
    s.own = r.Get<std::uint64_t>();
    s.direct_energy = r.Get<double>();
    s.current = r.GetVector<double>();
    s.transfer = r.GetVector<double>();
    const std::uint64_t size = s.vertices * std::uint64_t(s.channels) * std::uint64_t(s.coefficients);
    if (!r.AtEnd() || s.current.size() != size || s.transfer.size() != size || s.own > s.vertices)
      throw std::out_of_range("layout");
    return s;
  } catch (const std::out_of_range&) {
    why = "corrupt layout";
    return std::nullopt;
  }
}

}  // namespace prt
