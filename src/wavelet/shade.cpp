#include "wavelet/shade.h"

#include <algorithm>

#include "core/error.h"
#include "core/parallel.h"

namespace prt {

std::vector<glm::vec4> BaseLight(const TexelSh& base, const CubeRgb& texels) {
  std::vector<glm::vec4> sh(base.count(), glm::vec4(0.0f));
  std::vector<double> l(base.count());
  for (int c = 0; c < 3; ++c) {
    base.OfLight(texels.c[c], l.data());
    for (int j = 0; j < base.count(); ++j) sh[j][c] = static_cast<float>(l[j]);
  }
  return sh;
}

WaveletLight PackWaveletLight(const CubeRgb& coeffs, std::vector<glm::vec4> sh) {
  WaveletLight light;
  light.sh = std::move(sh);
  const std::size_t n = coeffs.c[0].size();
  light.rgb.resize(n);
  for (std::size_t k = 0; k < n; ++k)
    light.rgb[k] = glm::vec4(float(coeffs.c[0][k]), float(coeffs.c[1][k]), float(coeffs.c[2][k]), 0.0f);
  return light;
}

glm::vec4 BaseDirectLight(const WaveletTransport& transport, std::size_t v, const WaveletLight& light) {
  if (transport.base_lmax < 0) return glm::vec4(0.0f);
  const std::size_t n = static_cast<std::size_t>(CoeffCount(transport.base_lmax));
  if (light.sh.size() < n) throw Error("wavelet light: the transport's SH base has " + std::to_string(n) +
                                       " coefficients, the light " + std::to_string(light.sh.size()));
  glm::vec4 sum(0.0f);
  const float* s = transport.base.data() + v * n;
  for (std::size_t j = 0; j < n; ++j) sum += s[j] * light.sh[j];
  return sum;
}

glm::vec4 DirectLight(const WaveletTransport& transport, std::size_t v, const WaveletLight& light) {
  const std::size_t face = static_cast<std::size_t>(transport.face_size) * transport.face_size;
  glm::vec4 means(0.0f), details(0.0f);
  for (int f = 0; f < 6; ++f) means += transport.means[6 * v + f] * light.rgb[f * face];
  for (std::uint64_t j = transport.offsets[v]; j < transport.offsets[v + 1]; ++j)
    details += float(transport.value[j]) * light.rgb[transport.index[j]];
  return BaseDirectLight(transport, v, light) + means + transport.scale[v] * details;
}

WaveletLight TurnedWaveletLight(const LightCube& cube, const glm::dmat3& turn, int light_terms,
                                const std::vector<double>& weights, const TexelSh* base, CubeRgb& coeffs) {
  const int size = cube.grid().size();
  cube.Resample(turn, coeffs);
  std::vector<glm::vec4> sh;
  if (base && light_terms <= 0) sh = BaseLight(*base, coeffs);
  CubeToHaar(size, coeffs);
  if (light_terms > 0) {
    KeepLightTerms(weights, static_cast<std::size_t>(light_terms), coeffs);
    if (base) {
      CubeRgb kept = coeffs;
      CubeFromHaar(size, kept);
      sh = BaseLight(*base, kept);
    }
  }
  return PackWaveletLight(coeffs, std::move(sh));
}

std::vector<glm::vec3> ShadeWavelet(const Mesh& mesh, const WaveletTransport& transport, const WaveletLight& light,
                                    const ShRgb& sh_light, bool albedo) {
  const Transport& bounce = transport.bounce;
  const bool bounced = !bounce.coeffs.empty();
  const int count = bounced ? std::min<int>(CoeffCount(bounce.lmax), static_cast<int>(sh_light.size())) : 0;
  std::vector<glm::vec3> colors(mesh.vertex_count());
  ParallelFor(colors.size(), 1024, [&](std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v) {
      const glm::vec4 direct = DirectLight(transport, v, light);
      glm::dvec3 sum(direct.x, direct.y, direct.z);
      for (int c = 0; c < 3 && bounced; ++c) {
        const float* t = bounce.at(v, c);
        double s = 0.0;
        for (int k = 0; k < count; ++k) s += sh_light[k][c] * t[k];
        sum[c] += s;
      }
      colors[v] = albedo ? glm::vec3(glm::dvec3(mesh.albedo[v]) * sum) : glm::vec3(sum);
    }
  });
  return colors;
}

glm::vec3 ShadeDense(const float* coeffs, const WaveletLight& light) {
  glm::dvec3 sum(0.0);
  for (std::size_t k = 0; k < light.rgb.size(); ++k)
    sum += double(coeffs[k]) * glm::dvec3(light.rgb[k].x, light.rgb[k].y, light.rgb[k].z);
  return glm::vec3(sum);
}

}  // namespace prt
