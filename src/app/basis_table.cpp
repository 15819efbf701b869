#include "app/basis_table.h"

#include <string>

#include "app/pipeline.h"
#include "core/log.h"
#include "cpca/cpca_transfer.h"
#include "precompute/transport.h"
#include "sh/axis_rotation.h"
#include "sh_basis/frame_light.h"
#include "wavelet/frame_light.h"

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

/// The SH transport and what a frame reads of it: with a glossy orbit's matrices compressed by
/// clustered PCA (--cpca), the model in place of the full matrices.
struct ShData {
  Transport transport;
  CpcaTransfer cpca;
};

PreparedBasis PrepareSh(const BasisInputs& in) {
  auto data = std::make_shared<ShData>();
  data->transport = ComputeSceneTransport(in.mesh, in.scene, in.cache, in.seen, &in.camera, in.matrices);
  const bool compressed = in.matrices && in.cpca.clusters > 0;
  if (compressed) data->cpca = CompressSceneMatrices(data->transport, in.cpca.clusters, in.cpca.terms);
  PreparedBasis prepared;
  prepared.light = MakeShFrameLight(data->transport, in.light, in.axis, compressed ? &data->cpca : nullptr);
  const ShData* kept = data.get();
  prepared.relight = [kept, compressed](const Environment&, const ShRgb& light, const glm::dvec3& axis, int) {
    return MakeShFrameLight(kept->transport, light, axis, compressed ? &kept->cpca : nullptr);
  };
  const AxisRotation rotation(in.axis, data->transport.lmax);
  Summary("rotation: " + rotation.Describe() + "; only the " + std::to_string(CoeffCount(data->transport.lmax)) +
          " coefficients the transport has are turned");
  prepared.transport = std::move(data);
  return prepared;
}

/// SH's light alone: the light's bands as the transport would hold them (ComputeSceneTransport
/// computes at --lmax), none of its coefficients.
PreparedBasis PrepareShLight(const BasisInputs& in) {
  auto transport = std::make_shared<Transport>();
  transport->lmax = in.scene.lmax;
  PreparedBasis prepared;
  prepared.light = MakeShFrameLight(*transport, in.light, in.axis);
  const Transport* kept = transport.get();
  prepared.relight = [kept](const Environment&, const ShRgb& light, const glm::dvec3& axis, int) {
    return MakeShFrameLight(*kept, light, axis);
  };
  prepared.transport = std::move(transport);
  return prepared;
}

PreparedBasis PrepareWavelet(const BasisInputs& in) {
  TransportOptions sh = TransportOptionsOf(in.scene);
  sh.seen = in.seen;
  if (sh.mode == TransportMode::kInterreflection && !in.scene.lmax_why.empty()) Summary("bounce lmax: " + in.scene.lmax_why);
  auto transport = std::make_shared<WaveletTransport>(SceneWavelets(in.mesh, sh, in.scene.wavelet, in.env, in.cache));
  PreparedBasis prepared;
  prepared.light = MakeWaveletFrameLight(*transport, in.env, in.light, in.axis, in.scene.wavelet.light_terms,
                                         in.scene.wavelet.light_selection);
  const WaveletTransport* kept = transport.get();
  const WaveletOptions w = in.scene.wavelet;
  prepared.relight = [kept, w](const Environment& env, const ShRgb& light, const glm::dvec3& axis, int terms) {
    return MakeWaveletFrameLight(*kept, env, light, axis, terms, w.light_selection);
  };
  Summary("rotation: the environment turned and spread onto the wavelet cube each frame (its energy kept exactly, "
          "a compact source's light moving smoothly between texels: wavelet/light_cube.h)" +
          std::string(transport->bounce.coeffs.empty() ? "" : "; the bounces' SH light turned by its band matrices"));
  prepared.transport = std::move(transport);
  return prepared;
}

/// The wavelets' light alone: the cube of --cube-size, no vertices, no bounces.
PreparedBasis PrepareWaveletLight(const BasisInputs& in) {
  auto transport = std::make_shared<WaveletTransport>();
  transport->face_size = in.scene.wavelet.face_size;
  PreparedBasis prepared;
  prepared.light = MakeWaveletFrameLight(*transport, in.env, in.light, in.axis, in.scene.wavelet.light_terms,
                                         in.scene.wavelet.light_selection);
  const WaveletTransport* kept = transport.get();
  const WaveletOptions w = in.scene.wavelet;
  prepared.relight = [kept, w](const Environment& env, const ShRgb& light, const glm::dvec3& axis, int terms) {
    return MakeWaveletFrameLight(*kept, env, light, axis, terms, w.light_selection);
  };
  prepared.transport = std::move(transport);
  return prepared;
}

}  // namespace

const std::vector<Basis>& Bases() {
  static const std::vector<Basis> bases = {
      {"sh", "", true, true, true, true, false, {}, -1, "", "transport.cache", PrepareSh, PrepareShLight},
      {"wavelet",
       "wavelet keeps each vertex's direct light in Haar wavelets on a cube (all-frequency: sharp shadows of small "
       "bright sources), its bounces in SH at --lmax (4 unless given)",
       false, false, false, false, true, {"--cube-size", "--wavelet-terms", "--light-terms"}, kWaveletBounceLmax,
       kWaveletBounceLmaxWhy, "wavelet.cache",
       PrepareWavelet, PrepareWaveletLight},
  };
  return bases;
}

const Basis* DefaultBasis() { return &Bases().front(); }

const Basis* FindBasis(const std::string& name) {
  for (const Basis& b : Bases())
    if (name == b.name) return &b;
  return nullptr;
}

std::vector<std::string> BasisNames() {
  std::vector<std::string> names;
  for (const Basis& b : Bases()) names.push_back(b.name);
  return names;
}

}  // namespace prt
