#include "precompute/light.h"

#include <algorithm>
#include <vector>

#include "core/parallel.h"
#include "core/simd.h"
#include "sh/basis.h"

namespace prt {
namespace {

/// Texels per basis batch: 256 x 81 doubles (lmax 8) stay in L2 cache.
constexpr std::size_t kBatch = 256;

/// sums[c * count + k] += sum_i basis[k * n + i] * w_c[i] for the channels c = r, g, b.
/// Four interleaved partial sums per channel: independent chains that fill vector lanes
/// without reassociating any one sum, so every build rounds the same way.
PRT_VECTORIZED
void Accumulate(int count, std::size_t n, const double* basis, const double* wr, const double* wg,
                const double* wb, double* sums) {
  for (int k = 0; k < count; ++k) {
    const double* yk = basis + static_cast<std::size_t>(k) * n;
    double r[4] = {0, 0, 0, 0}, g[4] = {0, 0, 0, 0}, b[4] = {0, 0, 0, 0};
    std::size_t i = 0;
    for (; i + 4 <= n; i += 4)
      for (int j = 0; j < 4; ++j) {
        r[j] += yk[i + j] * wr[i + j];
        g[j] += yk[i + j] * wg[i + j];
        b[j] += yk[i + j] * wb[i + j];
      }
    for (; i < n; ++i) r[0] += yk[i] * wr[i], g[0] += yk[i] * wg[i], b[0] += yk[i] * wb[i];
    sums[k] += (r[0] + r[1]) + (r[2] + r[3]);
    sums[count + k] += (g[0] + g[1]) + (g[2] + g[3]);
    sums[2 * count + k] += (b[0] + b[1]) + (b[2] + b[3]);
  }
}

/// Scratch space for projecting up to kBatch texels at a time.
struct Batch {
  std::vector<double> x, y, z, wr, wg, wb, basis;

  /// Adds sum_i Y_k(dir_i) solid_angle_i radiance_i to sums (r[0..count), g[...], b[...]).
  void Project(int lmax, const Texel* texels, std::size_t n, double* sums) {
    const int count = CoeffCount(lmax);
    for (auto* v : {&x, &y, &z, &wr, &wg, &wb}) v->resize(n);
    basis.resize(static_cast<std::size_t>(count) * n);
    for (std::size_t i = 0; i < n; ++i) {
      x[i] = texels[i].dir.x, y[i] = texels[i].dir.y, z[i] = texels[i].dir.z;
      wr[i] = texels[i].solid_angle * texels[i].radiance.x;
      wg[i] = texels[i].solid_angle * texels[i].radiance.y;
      wb[i] = texels[i].solid_angle * texels[i].radiance.z;
    }
    EvalBasisBatch(lmax, n, x.data(), y.data(), z.data(), basis.data(), n);
    Accumulate(count, n, basis.data(), wr.data(), wg.data(), wb.data(), sums);
  }
};

}  // namespace

ShRgb ProjectLight(const Environment& env, int lmax) {
  const int count = CoeffCount(lmax);
  const std::size_t rows = env.RowCount();
  // At most 64 chunks of whole rows: their boundaries depend on the map only.
  const std::size_t grain = std::max<std::size_t>(1, (rows + 63) / 64);
  const std::size_t chunks = ChunkCount(rows, grain);
  // Per chunk, channel-major sums (r[0..count), g[...], b[...]) so the inner loop vectorises.
  std::vector<std::vector<double>> chunk_sums(chunks);

  ParallelFor(rows, grain, [&](std::size_t begin, std::size_t end) {
    std::vector<double> chunk(3 * count, 0.0), row_sum(3 * count);
    std::vector<Texel> texels;
    Batch batch;
    for (std::size_t r = begin; r < end; ++r) {
      env.Row(r, texels);
      std::fill(row_sum.begin(), row_sum.end(), 0.0);
      for (std::size_t first = 0; first < texels.size(); first += kBatch) {
        const std::size_t n = std::min(kBatch, texels.size() - first);
        batch.Project(lmax, &texels[first], n, row_sum.data());
      }
      for (int k = 0; k < 3 * count; ++k) chunk[k] += row_sum[k];
    }
    chunk_sums[begin / grain] = std::move(chunk);
  });

  ShRgb coeffs(count, glm::dvec3(0.0));
  for (const auto& chunk : chunk_sums)
    for (int k = 0; k < count; ++k) coeffs[k] += glm::dvec3(chunk[k], chunk[count + k], chunk[2 * count + k]);
  env.AddAnalyticProjection(lmax, coeffs);
  return coeffs;
}

}  // namespace prt
