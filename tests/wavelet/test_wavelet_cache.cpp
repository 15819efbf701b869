// The wavelet transport cache (wavelet/transport_cache.h) must give back the very transport it was
// given, and never one made from other inputs: a stale or damaged cache is a silently wrong
// picture. In the library: the round trip field by field, the key one input at a time, every
// damaged byte refused. (Through the binary: test_wavelet_cache_cli.cpp.)
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <set>
#include <string>

#include "core/atomic_file.h"
#include "core/hash.h"
#include "geometry/mesh_ops.h"
#include "geometry/procedural.h"
#include "precompute_io/transport_cache.h"
#include "tests/test_support.h"
#include "tests/wavelet/synthetic_transport.h"
#include "wavelet/transport_cache.h"

namespace prt {
namespace {

/// The size of WaveletTransport when the cache's format was written: a field added since is not
/// in the file. Add it to the format (and its version), to test::SyntheticWaveletTransport()
/// (synthetic_transport.h) and to CheckSame(), then update this (x86-64, libstdc++).
constexpr std::size_t kCachedStructSize = 352;

/// The header's bytes (transport_cache.h): each of them changed must be refused.
constexpr std::size_t kHeaderBytes = 96;

/// A sphere resting on a floor: concave, so rays, seeds and bounces all change its transport.
Mesh SphereOnFloor() {
  Mesh m = MakeSphere(8, 1.0f, glm::vec3(0.0f, 1.0f, 0.0f));
  AppendMesh(m, MakePlane(4.0f, 4));
  SetUniformAlbedo(m, glm::vec3(0.8f, 0.6f, 0.4f));
  return m;
}


template <class T>
bool SameBytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

bool SameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// Every field of WaveletTransport, bit for bit.
void CheckSame(const WaveletTransport& a, const WaveletTransport& b) {
  CHECK(a.face_size == b.face_size);
  CHECK(a.vertices == b.vertices);
  CHECK(a.base_lmax == b.base_lmax);
  CHECK(SameBytes(a.base, b.base));
  CHECK(SameBytes(a.means, b.means));
  CHECK(SameBytes(a.offsets, b.offsets));
  CHECK(SameBytes(a.index, b.index));
  CHECK(SameBytes(a.value, b.value));
  CHECK(SameBytes(a.scale, b.scale));
  CHECK(a.bounce.lmax == b.bounce.lmax);
  CHECK(a.bounce.channels == b.bounce.channels);
  CHECK(a.bounce.vertices == b.bounce.vertices);
  CHECK(SameBytes(a.bounce.coeffs, b.bounce.coeffs));
  CHECK(SameBytes(a.bounce.glossy, b.bounce.glossy));
  CHECK(SameBytes(a.bounce.matrices, b.bounce.matrices));
  CHECK(a.bounce.material.Name() == b.bounce.material.Name());
  CHECK(SameBytes(a.probes, b.probes));
  CHECK(SameBytes(a.probe_coeffs, b.probe_coeffs));
  CHECK(SameBits(a.kept_energy, b.kept_energy));
  CHECK(a.rays == b.rays);
  CHECK(SameBits(a.seconds, b.seconds));
}

/// What ReadWaveletCache says of the file `bytes` (written to `path`) under `key`: "reused" or its
/// reason.
std::string Verdict(const std::string& path, const std::string& bytes, std::uint64_t key) {
  WriteFileAtomic(path, bytes);
  std::string why;
  const bool read = ReadWaveletCache(path, key, why).has_value();
  CHECK(read == (why == "reused"));
  return why;
}

}  // namespace

TEST_SUITE("wavelet") {
  TEST_CASE("wavelet cache: a field added to the transport is a field added to the cache") {
    // The round trips below compare the fields this file knows; one added to WaveletTransport
    // and not to the cache would come back at its default from every cached run.
    CHECK_MESSAGE(sizeof(WaveletTransport) == kCachedStructSize,
                  "WaveletTransport changed: add the new field to wavelet/transport_cache.{h,cpp} (and its format "
                  "version), to test::SyntheticWaveletTransport() and CheckSame(), then update kCachedStructSize");
  }

  TEST_CASE("wavelet cache: every field comes back bit for bit") {
    const std::string dir = test::ScratchDir("wavelet_cache_round_trip");
    // Every field set by hand, then real transports: shadowed (no bounces) and with bounces.
    const WaveletTransport synthetic = test::SyntheticWaveletTransport();
    WriteWaveletCache(dir + "/synthetic.cache", synthetic, 42);
    std::string why;
    const auto back = ReadWaveletCache(dir + "/synthetic.cache", 42, why);
    REQUIRE_MESSAGE(back, why);
    CheckSame(synthetic, *back);

    const Mesh mesh = SphereOnFloor();
    for (const TransportMode mode : {TransportMode::kShadowed, TransportMode::kInterreflection}) {
      TransportOptions sh;
      sh.mode = mode;
      sh.samples = 64;
      WaveletOptions w;
      w.face_size = 8;
      w.budget = 40;
      const WaveletTransport t = ComputeWaveletTransport(mesh, sh, w, nullptr);
      const std::uint64_t key = WaveletTransportKey(mesh, sh, w);
      const std::string path = dir + "/" + TransportModeName(mode) + ".cache";
      WriteWaveletCache(path, t, key);
      const auto read = ReadWaveletCache(path, key, why);
      CAPTURE(TransportModeName(mode));
      REQUIRE_MESSAGE(read, why);
      CHECK(why == "reused");
      CHECK(read->bounce.coeffs.empty() == (mode == TransportMode::kShadowed));
      CheckSame(t, *read);
    }
  }

  TEST_CASE("wavelet cache key: every input of the stored transport changes it, the frame's light does not") {
    const Mesh mesh = SphereOnFloor();
    TransportOptions base_sh;
    base_sh.samples = 64;
    base_sh.hidden_samples = 64;
    const WaveletOptions base_w;
    std::map<std::string, std::uint64_t> keys;
    keys["base"] = WaveletTransportKey(mesh, base_sh, base_w);
    CHECK(WaveletTransportKey(mesh, base_sh, base_w) == keys["base"]);  // a function of its inputs only
    const auto with = [&](const std::string& name, auto change) {
      Mesh m = mesh;
      TransportOptions sh = base_sh;
      WaveletOptions w = base_w;
      change(m, sh, w);
      keys[name] = WaveletTransportKey(m, sh, w);
    };
    // The wavelets' own options that shape the stored coefficients.
    with("face size", [](Mesh&, TransportOptions&, WaveletOptions& w) { w.face_size = 16; });
    with("budget", [](Mesh&, TransportOptions&, WaveletOptions& w) { w.budget = 513; });
    with("split", [](Mesh&, TransportOptions&, WaveletOptions& w) { w.split = 3; });
    with("selection", [](Mesh&, TransportOptions&, WaveletOptions& w) {
      w.selection = w.selection == Selection::kArea ? Selection::kMagnitude : Selection::kArea;
    });
    with("base lmax", [&](Mesh&, TransportOptions&, WaveletOptions& w) { w.base_lmax = base_w.base_lmax + 1; });
    with("no base", [](Mesh&, TransportOptions&, WaveletOptions& w) { w.base_lmax = -1; });
    // The SH options (the bounces, the rays' seed, the mode) and the mesh.
    with("seed", [](Mesh&, TransportOptions& o, WaveletOptions&) { o.seed = 2; });
    with("samples", [](Mesh&, TransportOptions& o, WaveletOptions&) { o.samples = 65, o.hidden_samples = 65; });
    with("mode", [](Mesh&, TransportOptions& o, WaveletOptions&) { o.mode = TransportMode::kInterreflection; });
    with("unshadowed", [](Mesh&, TransportOptions& o, WaveletOptions&) { o.mode = TransportMode::kUnshadowed; });
    with("lmax", [](Mesh&, TransportOptions& o, WaveletOptions&) { o.lmax = 3; });
    with("bounces", [](Mesh&, TransportOptions& o, WaveletOptions&) { o.bounces = 2; });
    with("moved vertex", [](Mesh& m, TransportOptions&, WaveletOptions&) { m.positions[5].y += 1e-6f; });
    with("albedo", [](Mesh& m, TransportOptions&, WaveletOptions&) { m.albedo[5].x = 0.5f; });
    // A vertex no frame shows takes one ray a texel even where --hidden-samples equals --samples
    // (where the SH key leaves `seen` out).
    with("hidden vertex", [](Mesh& m, TransportOptions& o, WaveletOptions&) {
      o.seen.assign(m.vertex_count(), 1);
      o.seen[5] = 0;
    });
    with("other hidden vertex", [](Mesh& m, TransportOptions& o, WaveletOptions&) {
      o.seen.assign(m.vertex_count(), 1);
      o.seen[6] = 0;
    });
    std::set<std::uint64_t> distinct;
    for (const auto& [name, key] : keys) {
      CAPTURE(name);
      CHECK(distinct.insert(key).second);
    }
    // Kept light terms are a frame's choice, not the transport's: the cache serves any of them.
    WaveletOptions terms = base_w;
    terms.light_terms = 100;
    CHECK(WaveletTransportKey(mesh, base_sh, terms) == keys["base"]);
    // The SH transport's own key is another: a file of one basis never matches the other's key.
    CHECK(TransportKey(mesh, base_sh) != keys["base"]);
  }

  TEST_CASE("wavelet cache: truncated, damaged, of another version or of the SH basis, it is refused with a reason") {
    const std::string dir = test::ScratchDir("wavelet_cache_refused");
    const std::string good_path = dir + "/good.cache", path = dir + "/damaged.cache";
    constexpr std::uint64_t kKey = 0x1234567890abcdefULL;
    WriteWaveletCache(good_path, test::SyntheticWaveletTransport(), kKey);
    const std::string good = ReadFile(good_path);
    REQUIRE(good.size() > kHeaderBytes);
    CHECK(Verdict(path, good, kKey) == "reused");

    std::string why;
    CHECK(!ReadWaveletCache(dir + "/missing.cache", kKey, why));
    CHECK(why == "no cache yet");
    CHECK(Verdict(path, good, kKey + 1) == "made from other inputs");
    CHECK(Verdict(path, "", kKey) == "not a prt cache file");
    CHECK(Verdict(path, ReadFile(test::Fixture("cache/text.cache")), kKey) == "not a prt cache file");

    // Cut anywhere: in the magic, in the header, in the arrays, one byte short; and one too many.
    for (const std::size_t size : {std::size_t(5), std::size_t(8), std::size_t(50), kHeaderBytes - 1, kHeaderBytes,
                                   good.size() / 2, good.size() - 1}) {
      CAPTURE(size);
      const std::string verdict = Verdict(path, good.substr(0, size), kKey);
      CHECK(verdict != "reused");
      CHECK((verdict.find("truncated") != std::string::npos || (size < 8 && verdict == "not a prt cache file")));
    }
    CHECK(Verdict(path, good + '\0', kKey).find("oversized") != std::string::npos);

    // Another format version: said as such (the byte after the magic is the version's lowest).
    std::string other_version = good;
    other_version[8] = 2;
    CHECK(Verdict(path, other_version, kKey) == "cache format version 2 (expected 1)");

    // Every byte of the file changed, one at a time: none is taken (the checksum covers the
    // header's own fields, kept_energy and seconds among them, as well as the arrays).
    std::size_t refused = 0;
    for (std::size_t i = 0; i < good.size(); ++i) {
      std::string damaged = good;
      damaged[i] = char(damaged[i] ^ 0x10);
      const std::string verdict = Verdict(path, damaged, kKey);
      CAPTURE(i);
      CHECK(verdict != "reused");
      CHECK(!verdict.empty());
      if (i >= kHeaderBytes) CHECK(verdict == "checksum mismatch (corrupted)");
      refused += verdict != "reused";
    }
    CHECK(refused == good.size());

    // The SH basis's cache is not the wavelets', and the other way round.
    Transport sh;
    sh.lmax = 1;
    sh.vertices = 2;
    sh.coeffs.assign(8, 0.5f);
    WriteTransportCache(dir + "/sh.cache", sh, kKey);
    CHECK(Verdict(path, ReadFile(dir + "/sh.cache"), kKey) == "an SH transport cache (--basis sh), not a wavelet one");
    CHECK(!ReadTransportCache(good_path, kKey, why));
    CHECK(why == "not a prt cache file");
    CHECK(StartsLikeWaveletCache(good_path));
    CHECK(!StartsLikeWaveletCache(dir + "/sh.cache"));
    CHECK(!StartsLikeTransportCache(good_path));
  }

  TEST_CASE("wavelet cache: a detail index at the texel count is refused, the last texel's is read") {
    // A damaged cache whose checksum was made to match (as a writer with a bug would make it):
    // a detail index of 6 F^2, one past the last texel, would read past the end of the light's
    // coefficients on every frame. The reader's bound is index < 6 F^2; 6 F^2 - 1 is the last
    // texel, a valid index.
    const std::string dir = test::ScratchDir("wavelet_cache_index_bound");
    const std::string path = dir + "/damaged.cache";
    constexpr std::uint64_t kKey = 7;
    const WaveletTransport t = test::SyntheticWaveletTransport();
    const std::size_t texels = 6 * std::size_t(t.face_size) * std::size_t(t.face_size);
    WriteWaveletCache(path, t, kKey);
    const std::string good = ReadFile(path);
    // The index array's place (transport_cache.h): after the header, base, means, scale and offsets.
    const std::size_t index_at = kHeaderBytes + sizeof(float) * (t.base.size() + t.means.size() + t.scale.size()) +
                                 sizeof(std::uint64_t) * t.offsets.size();
    REQUIRE(index_at + sizeof(std::uint16_t) * t.index.size() <= good.size());
    // The file with detail j's index set to `index`, its checksum (at byte 64: FNV-1a of the file
    // with that field 0, the header's fields then the arrays in file order) made to match.
    const auto with_index = [&](std::size_t j, std::size_t index) {
      std::string bytes = good;
      const std::uint16_t stored = static_cast<std::uint16_t>(index);
      REQUIRE(stored == index);
      std::memcpy(&bytes[index_at + sizeof stored * j], &stored, sizeof stored);
      constexpr std::size_t kChecksumAt = 64;
      const std::uint64_t zero = 0;
      std::memcpy(&bytes[kChecksumAt], &zero, sizeof zero);
      const std::uint64_t sum = Fnv1a(bytes.data(), bytes.size());
      std::memcpy(&bytes[kChecksumAt], &sum, sizeof sum);
      return bytes;
    };
    CHECK(Verdict(path, with_index(0, t.index[0]), kKey) == "reused");  // the checksum made as the writer makes it
    // The last detail of each vertex that has one (each vertex's indices increase): at the
    // texel count refused, at the last texel read back with that index.
    std::size_t damaged = 0;
    for (std::size_t v = 0; v < t.vertices; ++v) {
      if (t.offsets[v + 1] == t.offsets[v]) continue;
      const std::size_t last = t.offsets[v + 1] - 1;
      CAPTURE(v);
      const std::string refused = Verdict(path, with_index(last, texels), kKey);
      CHECK(refused.find("corrupt indices") != std::string::npos);
      CHECK(refused.find(std::to_string(texels)) != std::string::npos);  // says which bound it broke
      CHECK(Verdict(path, with_index(last, texels + 1), kKey).find("corrupt indices") != std::string::npos);
      if (last == t.offsets[v] || t.index[last - 1] < texels - 1) {
        CHECK(Verdict(path, with_index(last, texels - 1), kKey) == "reused");
        std::string why;
        const auto read = ReadWaveletCache(path, kKey, why);
        REQUIRE_MESSAGE(read, why);
        CHECK(read->index[last] == texels - 1);
      }
      ++damaged;
    }
    CHECK(damaged == 4);
    // Through the reader's refusal, never an exception or a read: a cache of 65535 indices.
    CHECK(Verdict(path, with_index(t.offsets[1] - 1, 65535), kKey).find("corrupt indices") != std::string::npos);
  }

  TEST_CASE("wavelet cache: what cannot be written faithfully is an error, not a file") {
    const std::string dir = test::ScratchDir("wavelet_cache_write");
    // A transport whose arrays disagree with its counts would be read back as another one.
    WaveletTransport t = test::SyntheticWaveletTransport();
    t.value.pop_back();
    CHECK(test::ErrorMessage([&] { WriteWaveletCache(dir + "/a.cache", t, 1); }).find("disagree with its counts") !=
          std::string::npos);
    t = test::SyntheticWaveletTransport();
    t.base.push_back(1.0f);
    CHECK(!test::ErrorMessage([&] { WriteWaveletCache(dir + "/b.cache", t, 1); }).empty());
    CHECK(!std::filesystem::exists(dir + "/a.cache"));
    CHECK(!std::filesystem::exists(dir + "/b.cache"));
    // A folder that does not exist: the cause named.
    const std::string missing = dir + "/no/such/folder/c.cache";
    CHECK(test::ErrorMessage([&] { WriteWaveletCache(missing, test::SyntheticWaveletTransport(), 1); }).find("c.cache") != std::string::npos);
  }

  TEST_CASE("wavelet cache: a new cache replaces the old by renaming, never by writing over it") {
    // A second name (a hard link) of the old file keeps the old bytes: the new cache went to a
    // file of its own and was renamed over the first name. Written in place, both names would
    // show the new bytes (and a crash midway would leave a torn cache).
    const std::string dir = test::ScratchDir("wavelet_cache_atomic");
    const std::string path = dir + "/w.cache", second = dir + "/second_name";
    WriteWaveletCache(path, test::SyntheticWaveletTransport(), 1);
    const std::string old = ReadFile(path);
    std::filesystem::create_hard_link(path, second);
    WriteWaveletCache(path, test::SyntheticWaveletTransport(), 2);
    CHECK(ReadFile(second) == old);
    CHECK(ReadFile(path) != old);
    std::string why;
    CHECK(ReadWaveletCache(path, 2, why));
  }

}

}  // namespace prt
