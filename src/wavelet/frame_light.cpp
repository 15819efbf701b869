#include "wavelet/frame_light.h"

#include <glm/geometric.hpp>

#include "sh/axis_rotation.h"
#include "wavelet/cube_grid.h"
#include "wavelet/light_cube.h"
#include "wavelet/shade.h"
#include "wavelet/texel_sh.h"

namespace prt {
namespace {

class WaveletFrameLight : public FrameLight {
 public:
  WaveletFrameLight(const WaveletTransport& transport, const Environment& env, const ShRgb& sh_light,
                    const glm::dvec3& axis, int light_terms, Selection selection, int cells)
      : transport_(transport),
        grid_(transport.face_size),
        cube_(env, grid_, cells),
        axis_(glm::normalize(axis)),
        light_terms_(light_terms),
        weights_(SelectionWeights(transport.face_size, selection)),
        base_(transport.base_lmax >= 0 ? std::make_unique<TexelSh>(grid_, transport.base_lmax) : nullptr),
        sh_light_(transport.bounce.coeffs.empty() ? ShRgb{} : FirstBands(sh_light, transport.bounce.lmax)),
        rotation_(axis, transport.bounce.coeffs.empty() ? 0 : transport.bounce.lmax) {
    Turn(0.0);
  }

  void Turn(double angle) override {
    light_ = TurnedWaveletLight(cube_, AxisAngle(axis_, angle), light_terms_, weights_, base_.get(), kept_);
    CubeFromHaar(grid_.size(), kept_);  // the kept light back on the texels, for Kept()
    if (!sh_light_.empty()) lit_sh_ = rotation_.Rotate(sh_light_, angle);
  }
  void SetAxis(const glm::dvec3& axis) override {
    axis_ = glm::normalize(axis);
    rotation_ = AxisRotation(axis, transport_.bounce.coeffs.empty() ? 0 : transport_.bounce.lmax);
  }
  std::vector<glm::vec3> Shade(const Mesh& mesh, bool albedo, const glm::dvec3*) const override {
    return ShadeWavelet(mesh, transport_, light_, lit_sh_, albedo);
  }
  std::vector<glm::vec3> Glossy(const Mesh& mesh, const glm::dvec3*) const override {
    return std::vector<glm::vec3>(mesh.vertex_count(), glm::vec3(0.0f));
  }
  glm::vec3 Kept(const glm::dvec3& d) const override {
    const std::size_t t = grid_.TexelOf(d);
    return glm::vec3(float(kept_.c[0][t]), float(kept_.c[1][t]), float(kept_.c[2][t]));
  }
  bool HasGlossy() const override { return false; }
  int ViewCoefficients() const override { return 0; }
  double Coefficient(std::size_t, int) const override { return 0.0; }

 private:
  const WaveletTransport& transport_;
  CubeGrid grid_;
  LightCube cube_;
  glm::dvec3 axis_;
  int light_terms_;
  std::vector<double> weights_;
  std::unique_ptr<TexelSh> base_;  ///< the transport's SH base over the texels
  ShRgb sh_light_;
  AxisRotation rotation_;
  CubeRgb kept_;        ///< the frame's light as kept, on the texels
  WaveletLight light_;  ///< the same in the Haar basis, packed
  ShRgb lit_sh_;        ///< the frame's SH light, for the bounces
};

}  // namespace

std::unique_ptr<FrameLight> MakeWaveletFrameLight(const WaveletTransport& transport, const Environment& env,
                                                  const ShRgb& sh_light, const glm::dvec3& axis, int light_terms,
                                                  Selection selection, int cells) {
  return std::make_unique<WaveletFrameLight>(transport, env, sh_light, axis, light_terms, selection, cells);
}

}  // namespace prt
