#include "sh_basis/sh_basis.h"

#include <chrono>

#include "core/log.h"
#include "core/text.h"
#include "precompute_io/transport_cache.h"
#include "sh/axis_rotation.h"
#include "sh_basis/frame_light.h"
#include "sh_basis/scene_transport.h"

namespace prt {
namespace {

/// SH keeps no options of its own.
class ShSettings : public BasisSettings {};

/// The SH transport and what a frame reads of it: with a glossy orbit's matrices compressed by
/// clustered PCA (--cpca), the model in place of the full matrices.
class ShPrepared : public PreparedBasis {
 public:
  Transport transport;
  CpcaTransfer cpca;
  bool compressed = false;

  std::unique_ptr<FrameLight> Light(const Environment&, const ShRgb& light, const glm::dvec3& axis, int,
                                    LightQuality) const override {
    return MakeShFrameLight(transport, light, axis, compressed ? &cpca : nullptr);
  }
};

class Sh : public Basis {
 public:
  std::string Name() const override { return "sh"; }
  std::string Help() const override { return ""; }
  std::string Noun() const override { return "an SH"; }
  BasisTraits Traits() const override {
    BasisTraits t;
    t.course_files = true;
    t.glossy = true;
    t.coefficient_view = true;
    t.windowed_light = true;
    t.light_bands = true;
    t.takes_samples = true;
    t.shards = true;
    return t;
  }
  std::shared_ptr<const BasisSettings> ReadOptions(Args&) const override { return DefaultSettings(); }
  std::shared_ptr<const BasisSettings> DefaultSettings() const override { return std::make_shared<ShSettings>(); }
  std::string CommandLine(const BasisSettings&, int) const override { return ""; }
  std::string CacheName() const override { return "transport.cache"; }
  bool IsOwnCache(const std::string& path) const override { return StartsLikeTransportCache(path); }

  void CheckMemory(const Mesh& mesh, const TransportOptions& o, bool matrices) const override {
    if (matrices) CheckMatrixMemory(mesh, o.mode, o.lmax);
  }

  std::unique_ptr<PreparedBasis> Prepare(const BasisInputs& in) const override {
    auto prepared = std::make_unique<ShPrepared>();
    prepared->transport =
        ComputeSceneTransport(*this, in.mesh, in.transport, in.samples_from_rule, in.cache, in.camera, in.matrices,
                              in.sharded);
    prepared->compressed = in.matrices && in.cpca.clusters > 0;
    if (prepared->compressed)
      prepared->cpca = CompressSceneMatrices(prepared->transport, in.cpca.clusters, in.cpca.terms);
    const AxisRotation rotation(in.axis, prepared->transport.lmax);
    Summary("rotation: " + rotation.Describe() + "; only the " + std::to_string(CoeffCount(prepared->transport.lmax)) +
            " coefficients the transport has are turned");
    return prepared;
  }

  Transport ComputeBlock(const BasisInputs& in, const VertexBlock& block, std::uint64_t& key) const override {
    TransportOptions topts = SceneTransportOptions(in.transport, in.camera, in.matrices);
    key = TransportKey(in.mesh, topts);  // the whole run's: the key leaves the block out
    topts.block = block;
    const auto t0 = std::chrono::steady_clock::now();
    TransportReport report;
    Transport whole = ComputeTransport(in.mesh, topts, &report);
    Summary("transport: " + std::string(TransportModeName(topts.mode)) + ", lmax " + std::to_string(topts.lmax) +
            " of vertices " + std::to_string(block.begin) + " to " + std::to_string(block.end - 1) +
            Formatted(" [%.3f s]", SecondsSince(t0)) + "; " + std::to_string(report.rays) + " rays");
    return whole;
  }

  /// The light's bands as the transport would hold them (ComputeSceneTransport computes at
  /// --lmax), none of its coefficients.
  std::unique_ptr<PreparedBasis> PrepareLight(const BasisInputs& in) const override {
    auto prepared = std::make_unique<ShPrepared>();
    prepared->transport.lmax = in.transport.lmax;
    return prepared;
  }
};

}  // namespace

const Basis& ShBasis() {
  static const Sh basis;
  return basis;
}

}  // namespace prt
