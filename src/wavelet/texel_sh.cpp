#include "wavelet/texel_sh.h"

#include "sh/basis.h"
#include "sh/coeffs.h"

namespace prt {

TexelSh::TexelSh(const CubeGrid& grid, int lmax) : lmax_(lmax), count_(CoeffCount(lmax)), texels_(grid.texels()) {
  constexpr int kSplit = 4;
  std::vector<glm::dvec3> dirs;
  std::vector<double> omega;
  grid.SubTexels(kSplit, dirs, omega);
  ybar_.assign(static_cast<std::size_t>(count_) * texels_, 0.0);
  inv_area_.resize(texels_);
  std::vector<double> y(count_);
  for (std::size_t t = 0; t < texels_; ++t) {
    inv_area_[t] = 1.0 / grid.SolidAngle(t);
    for (std::size_t k = t * kSplit * kSplit; k < (t + 1) * kSplit * kSplit; ++k) {
      EvalBasis(lmax, dirs[k], y.data());
      for (int j = 0; j < count_; ++j) ybar_[j * texels_ + t] += omega[k] * y[j];
    }
  }
}

void TexelSh::Project(const double* integrals, double* s) const {
  for (int j = 0; j < count_; ++j) {
    const double* yj = ybar_.data() + j * texels_;
    double sum = 0.0;
    for (std::size_t t = 0; t < texels_; ++t) sum += integrals[t] * inv_area_[t] * yj[t];
    s[j] = sum;
  }
}

void TexelSh::Subtract(const double* s, double* integrals) const {
  for (int j = 0; j < count_; ++j) {
    const double* yj = ybar_.data() + j * texels_;
    const double sj = s[j];
    for (std::size_t t = 0; t < texels_; ++t) integrals[t] -= sj * yj[t];
  }
}

void TexelSh::OfLight(const std::vector<double>& means, double* l) const {
  for (int j = 0; j < count_; ++j) {
    const double* yj = ybar_.data() + j * texels_;
    double sum = 0.0;
    for (std::size_t t = 0; t < texels_; ++t) sum += means[t] * yj[t];
    l[j] = sum;
  }
}

}  // namespace prt
