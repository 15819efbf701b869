#include "precompute/reference_env_sampler.h"

#include <algorithm>
#include <cmath>

#include "core/color.h"
#include "core/constants.h"
#include "core/parallel.h"

namespace prt {
namespace {



/// The unit direction at height y (= cos theta about +Y) and azimuth phi.
glm::dvec3 Direction(double y, double phi) {
  y = std::clamp(y, -1.0, 1.0);
  const double s = std::sqrt((1.0 - y) * (1.0 + y));
  return {s * std::sin(phi), y, -s * std::cos(phi)};
}

/// Index of the interval of `cdf` (ascending, cdf[0] = 0, cdf[n] = 1) that holds u, and the
/// position of u inside it in [0, 1).
std::size_t Invert(const double* cdf, std::size_t n, double u, double& within) {
  const double* it = std::upper_bound(cdf, cdf + n + 1, u);
  std::size_t i = static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - cdf - 1, 0));
  i = std::min(i, n - 1);
  // Skip empty intervals (cannot be chosen with positive probability).
  while (i + 1 < n && cdf[i + 1] <= cdf[i]) ++i;
  const double width = cdf[i + 1] - cdf[i];
  within = width > 0 ? std::clamp((u - cdf[i]) / width, 0.0, std::nextafter(1.0, 0.0)) : 0.5;
  return i;
}

}  // namespace

EnvSampler::EnvSampler(const Environment& env, int rows, int cols, double defensive)
    : env_(env), rows_(rows), cols_(cols), cell_solid_angle_(4.0 * kPi / (double(rows) * cols)) {
  const std::size_t nr = static_cast<std::size_t>(rows), nc = static_cast<std::size_t>(cols);
  weight_.assign(nr * nc, 0.0);
  // Max luminance over 3 x 3 sub-points of each cell (corners included).
  ParallelFor(nr, 8, [&](std::size_t begin, std::size_t end) {
    for (std::size_t r = begin; r < end; ++r)
      for (std::size_t c = 0; c < nc; ++c) {
        double q = 0.0;
        for (int a = 0; a <= 2; ++a)
          for (int b = 0; b <= 2; ++b) {
            const double y = -1.0 + 2.0 * (double(r) + 0.5 * a) / rows;
            const double phi = 2.0 * kPi * (double(c) + 0.5 * b) / cols;
            const double lum = Luminance(env.Radiance(Direction(y, phi)));
            if (std::isfinite(lum)) q = std::max(q, lum);
          }
        weight_[r * nc + c] = q;
      }
  });
  double mean = 0.0;
  for (double q : weight_) mean += q;
  mean /= double(weight_.size());
  const double floor = mean > 0 ? defensive * mean : 1.0;
  for (double& q : weight_) q += floor;

  // Row marginal and per-row conditional CDFs.
  cell_cdf_.assign(nr * (nc + 1), 0.0);
  row_cdf_.assign(nr + 1, 0.0);
  for (std::size_t r = 0; r < nr; ++r) {
    double* cdf = cell_cdf_.data() + r * (nc + 1);
    for (std::size_t c = 0; c < nc; ++c) cdf[c + 1] = cdf[c] + weight_[r * nc + c];
    const double row_sum = cdf[nc];
    for (std::size_t c = 0; c <= nc; ++c) cdf[c] /= row_sum;
    row_cdf_[r + 1] = row_cdf_[r] + row_sum;
  }
  total_ = row_cdf_[nr];
  for (double& v : row_cdf_) v /= total_;
}

EnvSample EnvSampler::Sample(double u1, double u2) const {
  const std::size_t nc = static_cast<std::size_t>(cols_);
  double fy = 0, fx = 0;
  const std::size_t r = Invert(row_cdf_.data(), static_cast<std::size_t>(rows_), u1, fy);
  const std::size_t c = Invert(cell_cdf_.data() + r * (nc + 1), nc, u2, fx);
  EnvSample s;
  s.dir = Direction(-1.0 + 2.0 * (double(r) + fy) / rows_, 2.0 * kPi * (double(c) + fx) / cols_);
  s.pdf = weight_[r * nc + c] / (total_ * cell_solid_angle_);
  s.radiance = env_.Radiance(s.dir);
  return s;
}

double EnvSampler::Pdf(const glm::dvec3& dir) const {
  // Direction() inverted: y = cos theta about +Y, phi from -Z towards +X.
  const double y = std::clamp(dir.y, -1.0, 1.0);
  double phi = std::atan2(dir.x, -dir.z);
  if (phi < 0.0) phi += 2.0 * kPi;
  const int r = std::clamp(int((y + 1.0) * 0.5 * rows_), 0, rows_ - 1);
  const int c = std::clamp(int(phi / (2.0 * kPi) * cols_), 0, cols_ - 1);
  return weight_[std::size_t(r) * std::size_t(cols_) + std::size_t(c)] / (total_ * cell_solid_angle_);
}

}  // namespace prt
