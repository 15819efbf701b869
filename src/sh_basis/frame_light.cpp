#include "sh_basis/frame_light.h"

#include <glm/geometric.hpp>

#include "core/error.h"
#include "precompute/shade.h"
#include "sh/axis_rotation.h"
#include "sh/basis.h"
#include "sh/rotation.h"

namespace prt {
namespace {

class ShFrameLight : public FrameLight {
 public:
  ShFrameLight(const Transport& transport, const ShRgb& light, const glm::dvec3& axis, const CpcaTransfer* cpca)
      : transport_(transport), cpca_(cpca), light_(FirstBands(light, transport.lmax)), rotation_(axis, transport.lmax),
        lit_(light_) {}

  void Turn(double angle) override { lit_ = rotation_.Rotate(light_, angle); }
  void SetAxis(const glm::dvec3& axis) override { rotation_ = AxisRotation(axis, transport_.lmax); }
  std::vector<glm::vec3> Shade(const Mesh& mesh, bool albedo, const glm::dvec3* eye) const override {
    if (cpca_ && albedo && transport_.material.glossy) return ShadeVerticesCpca(mesh, transport_, *cpca_, lit_, albedo, Eye(eye));
    return ShadeVertices(mesh, transport_, lit_, albedo, eye);
  }
  void ShadeInto(const Mesh& mesh, bool albedo, const glm::dvec3* eye, std::vector<glm::vec3>& out) const override {
    if (albedo && transport_.material.glossy) {  // the lobe's shading has its own buffers
      out = Shade(mesh, albedo, eye);
      return;
    }
    ShadeVerticesInto(mesh, transport_, lit_, albedo, eye, out);
  }
  std::vector<glm::vec3> Glossy(const Mesh& mesh, const glm::dvec3* eye) const override {
    if (cpca_) return GlossyFromCpca(mesh, *cpca_, transport_.material, lit_, Eye(eye));
    return ShadeGlossy(mesh, transport_, lit_, eye);
  }
  glm::vec3 Kept(const glm::dvec3& d) const override {
    double y[CoeffCount(kMaxLmax)];
    EvalBasis(transport_.lmax, d, y);
    glm::dvec3 sum(0.0);
    for (std::size_t k = 0; k < lit_.size(); ++k) sum += y[k] * lit_[k];
    return glm::vec3(sum);
  }
  bool HasGlossy() const override { return transport_.material.glossy; }
  int ViewCoefficients() const override { return CoeffCount(transport_.lmax); }
  double Coefficient(std::size_t v, int k) const override { return transport_.at(v, 0)[k]; }

 private:
  static const glm::dvec3& Eye(const glm::dvec3* eye) {
    if (!eye) throw Error("shading by compressed transfer matrices needs the camera's eye (internal)");
    return *eye;
  }

  const Transport& transport_;
  const CpcaTransfer* cpca_;
  ShRgb light_;
  AxisRotation rotation_;
  ShRgb lit_;
};

}  // namespace

std::unique_ptr<FrameLight> MakeShFrameLight(const Transport& transport, const ShRgb& light, const glm::dvec3& axis,
                                             const CpcaTransfer* cpca) {
  return std::make_unique<ShFrameLight>(transport, light, axis, cpca);
}

}  // namespace prt
