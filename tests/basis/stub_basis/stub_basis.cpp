#include "tests/basis/stub_basis/stub_basis.h"

#include "options/option_table.h"

namespace prt {
namespace {

class StubSettings : public BasisSettings {
 public:
  explicit StubSettings(double g) : gain(g) {}
  double gain;
};

/// Every vertex the light's mean radiance (its SH band 0: L_00 Y_00) times the gain.
class StubLight : public FrameLight {
 public:
  StubLight(const ShRgb& light, double gain) : radiance_(glm::vec3(light.at(0) * 0.28209479177387814 * gain)) {}
  void Turn(double) override {}
  void SetAxis(const glm::dvec3&) override {}
  std::vector<glm::vec3> Shade(const Mesh& mesh, bool, const glm::dvec3*) const override {
    return std::vector<glm::vec3>(mesh.vertex_count(), radiance_);
  }
  bool HasGlossy() const override { return false; }
  std::vector<glm::vec3> Glossy(const Mesh& mesh, const glm::dvec3*) const override {
    return std::vector<glm::vec3>(mesh.vertex_count(), glm::vec3(0.0f));
  }
  glm::vec3 Kept(const glm::dvec3&) const override { return radiance_; }
  int ViewCoefficients() const override { return 0; }
  double Coefficient(std::size_t, int) const override { return 0.0; }

 private:
  glm::vec3 radiance_;
};

class StubPrepared : public PreparedBasis {
 public:
  explicit StubPrepared(double g) : gain(g) {}
  double gain;
  std::unique_ptr<FrameLight> Light(const Environment&, const ShRgb& light, const glm::dvec3&, int,
                                    LightQuality) const override {
    return std::make_unique<StubLight>(light, gain);
  }
};

class Stub : public Basis {
 public:
  std::string Name() const override { return "stub"; }
  std::string Help() const override { return "stub gives every vertex the light's mean"; }
  std::string Noun() const override { return "a stub"; }
  BasisTraits Traits() const override { return {}; }
  std::vector<OptionSpec> OwnOptions() const override {
    return {{"--stub-gain", "G", "stub basis: the mean light's gain, 0..10", "1"}};
  }
  std::shared_ptr<const BasisSettings> ReadOptions(Args& args) const override {
    return std::make_shared<StubSettings>(args.Accepts("--stub-gain") ? args.Double("--stub-gain", 1.0, 0.0, 10.0) : 1.0);
  }
  std::shared_ptr<const BasisSettings> DefaultSettings() const override { return std::make_shared<StubSettings>(1.0); }
  std::string CommandLine(const BasisSettings&, int) const override { return ""; }
  std::string CacheName() const override { return "stub.cache"; }
  bool IsOwnCache(const std::string&) const override { return false; }
  std::unique_ptr<PreparedBasis> Prepare(const BasisInputs& in) const override {
    return std::make_unique<StubPrepared>(SettingsAs<StubSettings>(in.own).gain);
  }
  std::unique_ptr<PreparedBasis> PrepareLight(const BasisInputs& in) const override { return Prepare(in); }
};

}  // namespace

const Basis& StubBasis() {
  static const Stub basis;
  return basis;
}

}  // namespace prt
