#include "precompute/light.h"

#include <algorithm>
#include <vector>

#include "core/parallel.h"
#include "sh/basis.h"

namespace prt {

ShRgb ProjectLight(const Environment& env, int lmax) {
  const int count = CoeffCount(lmax);
  const std::size_t rows = env.RowCount();
  // At most 64 chunks of whole rows: their boundaries depend on the map only.
  const std::size_t grain = std::max<std::size_t>(1, (rows + 63) / 64);
  const std::size_t chunks = ChunkCount(rows, grain);
  // Per chunk, channel-major sums (r[0..count), g[...], b[...]) so the inner loop vectorises.
  std::vector<std::vector<double>> chunk_sums(chunks);

  ParallelFor(rows, grain, [&](std::size_t begin, std::size_t end) {
    std::vector<double> chunk(3 * count, 0.0), row_sum(3 * count), y(count);
    std::vector<Texel> texels;
    for (std::size_t r = begin; r < end; ++r) {
      env.Row(r, texels);
      std::fill(row_sum.begin(), row_sum.end(), 0.0);
      double* sr = row_sum.data();
      double* sg = sr + count;
      double* sb = sg + count;
      for (const Texel& t : texels) {
        EvalBasis(lmax, t.dir, y.data());
        const double wr = t.solid_angle * t.radiance.x, wg = t.solid_angle * t.radiance.y,
                     wb = t.solid_angle * t.radiance.z;
        for (int k = 0; k < count; ++k) {
          sr[k] += y[k] * wr;
          sg[k] += y[k] * wg;
          sb[k] += y[k] * wb;
        }
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
