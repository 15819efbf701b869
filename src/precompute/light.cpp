#include "precompute/light.h"

#include <algorithm>
#include <vector>

#include "core/parallel.h"
#include "sh/basis.h"

namespace prt {
namespace {

/// Texels per basis batch: the batch size fixes the order of the sums (ProjectBasisBatch).
constexpr std::size_t kBatch = 256;

/// Scratch space for projecting up to kBatch texels at a time.
struct Batch {
  std::vector<double> x, y, z, wr, wg, wb;

  /// Adds sum_i Y_k(dir_i) solid_angle_i radiance_i to sums (r[0..count), g[...], b[...]).
  void Project(int lmax, const Texel* texels, std::size_t n, double* sums) {
    for (auto* v : {&x, &y, &z, &wr, &wg, &wb}) v->resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      x[i] = texels[i].dir.x, y[i] = texels[i].dir.y, z[i] = texels[i].dir.z;
      wr[i] = texels[i].solid_angle * texels[i].radiance.x;
      wg[i] = texels[i].solid_angle * texels[i].radiance.y;
      wb[i] = texels[i].solid_angle * texels[i].radiance.z;
    }
    ProjectBasisBatch(lmax, n, x.data(), y.data(), z.data(), wr.data(), wg.data(), wb.data(), sums);
  }
};

}  // namespace

ShRgb ProjectLight(const Environment& env, int lmax) {
  const int count = CoeffCount(lmax);
  const std::size_t rows = env.RowCount();
  // At most 64 chunks of whole rows: their boundaries depend on the map only.
  const std::size_t grain = std::max<std::size_t>(1, (rows + 63) / 64);
  const std::size_t chunks = ChunkCount(rows, grain);
  // Per chunk, channel-major sums (r[0..count), g[...], b[...]), ProjectBasisBatch's layout.
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
