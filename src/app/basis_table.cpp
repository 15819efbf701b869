#include "app/basis_table.h"

#include <string>

#include "app/pipeline.h"
#include "core/log.h"
#include "cpca/cpca_transfer.h"
#include "precompute/transport.h"
#include "sh/axis_rotation.h"
#include "sh_basis/frame_light.h"
#include "wavelet/frame_light.h"
#include "wavelet/summary.h"

namespace prt {
namespace {

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
  const AxisRotation rotation(in.axis, data->transport.lmax);
  Summary("rotation: " + rotation.Describe() + "; only the " + std::to_string(CoeffCount(data->transport.lmax)) +
          " coefficients the transport has are turned");
  prepared.transport = std::move(data);
  return prepared;
}

PreparedBasis PrepareWavelet(const BasisInputs& in) {
  TransportOptions sh = TransportOptionsOf(in.scene);
  sh.seen = in.seen;
  auto transport = std::make_shared<WaveletTransport>(ComputeSceneWavelets(in.mesh, sh, in.scene.wavelet, in.env));
  PreparedBasis prepared;
  prepared.light = MakeWaveletFrameLight(*transport, in.env, in.light, in.axis, in.scene.wavelet.light_terms,
                                         in.scene.wavelet.selection);
  Summary("rotation: the environment turned and resampled onto the wavelet cube each frame (each texel its mean "
          "radiance, the sun's energy kept exactly)" +
          std::string(transport->bounce.coeffs.empty() ? "" : "; the bounces' SH light turned by its band matrices"));
  prepared.transport = std::move(transport);
  return prepared;
}

}  // namespace

const std::vector<Basis>& Bases() {
  static const std::vector<Basis> bases = {
      {"sh", "", true, true, true, true, false, {}, PrepareSh},
      {"wavelet",
       "wavelet keeps each vertex's direct light in Haar wavelets on a cube (all-frequency: sharp shadows of small "
       "bright sources), its bounces in SH at --lmax",
       false, false, false, false, true, {"--cube-size", "--wavelet-terms", "--light-terms"}, PrepareWavelet},
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
