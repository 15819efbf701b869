#include "wavelet/wavelet_basis.h"

#include <algorithm>

#include "basis/cache_plan.h"
#include "core/log.h"
#include "options/option_table.h"
#include "wavelet/frame_light.h"
#include "wavelet/scene_wavelets.h"
#include "wavelet/study.h"
#include "wavelet/transport_cache.h"

namespace prt {
namespace {

/// The wavelets' bounces: lmax 4 unless --lmax is given. Measured (Intel Xeon, 2 vCPUs) on the
/// sample knot over its 40 x 40 ground under sky.hdr (the sky as `prt sample-files` writes it),
/// one bounce, default cube and budget, against prt reference (8192 directions, own error
/// 0.38 %): 1.59 % with the bounces at lmax 4, the direct light alone 1.26 % (shadowed), so the
/// bounces' own error is about sqrt(1.59^2 - 1.26^2) = 1.0 %, below the direct part's. At lmax 2
/// it was about 1.8 % (2.28 % in all beside a direct 1.44 %, measured with the details kept by
/// area), above it; lmax 8 took it to 1.50 % for three times the coefficients.
constexpr int kWaveletBounceLmax = 4;
constexpr const char* kWaveletBounceLmaxWhy =
    "lmax 4 chosen for wavelet bounces: their own error (measured about 1.0 % on the sample scene under sky.hdr, "
    "1.8 % at lmax 2) stays below the direct part's (1.3 %); --lmax sets it";

class WaveletSettings : public BasisSettings {
 public:
  explicit WaveletSettings(const WaveletOptions& o) : options(o) {}
  WaveletOptions options;
};

/// The wavelet transport and what a frame reads of it.
class WaveletPrepared : public PreparedBasis {
 public:
  WaveletTransport transport;
  Selection light_selection = WaveletOptions{}.light_selection;

  std::unique_ptr<FrameLight> Light(const Environment& env, const ShRgb& light, const glm::dvec3& axis, int light_terms,
                                    LightQuality quality) const override {
    return MakeWaveletFrameLight(transport, env, light, axis, light_terms, light_selection,
                                 quality == LightQuality::kInteractive ? kInteractiveCells : 0);
  }
};

class Wavelet : public Basis {
 public:
  std::string Name() const override { return "wavelet"; }
  std::string Help() const override {
    return "wavelet keeps each vertex's direct light in Haar wavelets on a cube (all-frequency: sharp shadows of "
           "small bright sources), its bounces in SH at --lmax (4 unless given)";
  }
  std::string Noun() const override { return "a wavelet"; }
  BasisTraits Traits() const override { return BasisTraits{}; }
  const BasisStudy* Study() const override { return &WaveletBasisStudy(); }

  std::vector<OptionSpec> OwnOptions() const override {
    const WaveletOptions d;
    return {{"--cube-size", "F", "wavelet basis: the cube's face size, a power of two from 8 to 64 (6 F^2 texels)",
             std::to_string(d.face_size)},
            {"--wavelet-terms", "N",
             "wavelet basis: coefficients kept per vertex, the 6 faces' means among them, 6..6 F^2 (4 bytes a detail)",
             std::to_string(d.budget)},
            {"--light-terms", "K", "wavelet basis: light coefficients kept per frame, the K most important (0: all), 0..6 F^2",
             d.light_terms ? std::to_string(d.light_terms) : "0 (all)"}};
  }

  std::shared_ptr<const BasisSettings> ReadOptions(Args& args) const override {
    const WaveletOptions d;
    WaveletOptions o;
    const auto has = [&args](const char* name) { return args.Accepts(name); };
    if (has("--cube-size")) {
      o.face_size = args.Int("--cube-size", d.face_size, 8, kMaxWaveletFace);
      if (o.face_size & (o.face_size - 1))
        args.Fail("--cube-size: " + std::to_string(o.face_size) + " is not a power of two (expected 8, 16, 32 or 64)");
    }
    const int texels = 6 * o.face_size * o.face_size;
    if (has("--wavelet-terms")) o.budget = args.Int("--wavelet-terms", d.budget, 6, texels);
    if (has("--light-terms")) o.light_terms = args.Int("--light-terms", d.light_terms, 0, texels);
    o.budget = std::min(o.budget, texels);
    return std::make_shared<WaveletSettings>(o);
  }
  std::shared_ptr<const BasisSettings> DefaultSettings() const override {
    return std::make_shared<WaveletSettings>(WaveletOptions{});
  }
  std::string CommandLine(const BasisSettings&, int light_terms) const override {
    return " --light-terms " + std::to_string(light_terms);
  }
  int MaxLightTerms(const BasisSettings& s) const override {
    const WaveletOptions& o = WaveletOptionsOf(s);
    return 6 * o.face_size * o.face_size;
  }
  int LightTerms(const BasisSettings& s) const override { return WaveletOptionsOf(s).light_terms; }

  int Lmax() const override { return kWaveletBounceLmax; }
  std::string LmaxWhy() const override { return kWaveletBounceLmaxWhy; }
  std::string CacheName() const override { return "wavelet.cache"; }
  bool IsOwnCache(const std::string& path) const override { return StartsLikeWaveletCache(path); }

  std::unique_ptr<PreparedBasis> Prepare(const BasisInputs& in) const override {
    const WaveletOptions& w = WaveletOptionsOf(in.own);
    if (in.transport.mode == TransportMode::kInterreflection && !in.lmax_why.empty()) Summary("bounce lmax: " + in.lmax_why);
    auto prepared = std::make_unique<WaveletPrepared>();
    prepared->transport = SceneWavelets(*this, in.mesh, in.transport, w, in.env, in.cache);
    prepared->light_selection = w.light_selection;
    Summary("rotation: the environment turned and spread onto the wavelet cube each frame (its energy kept exactly, "
            "a compact source's light moving smoothly between texels: wavelet/light_cube.h)" +
            std::string(prepared->transport.bounce.coeffs.empty() ? "" : "; the bounces' SH light turned by its band matrices"));
    return prepared;
  }

  /// The cube of --cube-size, no vertices, no bounces.
  std::unique_ptr<PreparedBasis> PrepareLight(const BasisInputs& in) const override {
    const WaveletOptions& w = WaveletOptionsOf(in.own);
    auto prepared = std::make_unique<WaveletPrepared>();
    prepared->transport.face_size = w.face_size;
    prepared->light_selection = w.light_selection;
    return prepared;
  }
};

}  // namespace

const Basis& WaveletBasis() {
  static const Wavelet basis;
  return basis;
}

const WaveletOptions& WaveletOptionsOf(const BasisSettings& settings) {
  return SettingsAs<WaveletSettings>(settings).options;
}

}  // namespace prt
